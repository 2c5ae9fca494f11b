#!/usr/bin/env bash
# Scale-out: the same sizing sweep as sweep_dask.py over GNU parallel
# (issue 19): one process per grid point, rows in grid order (--keep-order),
# so the output equals sweep_dask.py's.
#   PYTHONPATH=build/python examples/python/sweep_parallel.sh [JOBS] > parallel.csv
# Across machines: add --sshlogin host1,host2 (sreh_twin installed there).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
jobs="${1:-2}"
python="${PYTHON:-/usr/bin/python3}"
parallel --will-cite --keep-order -j "$jobs" "$python" "$here/size_point.py" {1} {2} \
  ::: 0 2000 5000 10000 15000 ::: 45 90 180
