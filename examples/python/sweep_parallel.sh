#!/usr/bin/env bash
# Scale-out: a sizing sweep over GNU parallel through the Python API
# (issue 19): one process per grid point (size_point.py), rows in grid order
# (--keep-order). For the CLI's sweep CSV use `sweep --shard {}/N` and
# `sweep merge` (docs/sizing.md); sweep_dask.py does that on a Dask cluster.
#   PYTHONPATH=build/python examples/python/sweep_parallel.sh [JOBS] > parallel.csv
# Across machines: add --sshlogin host1,host2 (sreh_twin installed there).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
jobs="${1:-2}"
python="${PYTHON:-/usr/bin/python3}"
parallel --will-cite --keep-order -j "$jobs" "$python" "$here/size_point.py" {1} {2} \
  ::: 0 2000 5000 10000 15000 ::: 45 90 180
