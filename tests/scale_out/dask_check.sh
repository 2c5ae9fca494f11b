#!/bin/bash
# Issue 31: examples/python/sweep_dask.py on a real Dask cluster of
# processes: a `dask scheduler` and two `dask worker` processes (Debian's
# python3-distributed), not an in-process cluster. The merged CSV is the
# CLI's `sweep` CSV byte for byte, and both workers ran shards. Stops exactly
# the three processes it started. Exit 77 (skipped) only without the package.
#   dask_check.sh SREH_TWIN PYTHON_PACKAGE_DIR EXAMPLE
set -euo pipefail
bin=$(realpath "$1")
pythonpath=$(realpath "$2")
example=$(realpath "$3")
if ! command -v dask > /dev/null || ! /usr/bin/python3 -c 'import distributed' 2> /dev/null; then
  echo "skipped: no dask / python3-distributed (./setup.sh installs it)"
  exit 77
fi
dir=$(mktemp -d)
pids=()
# Workers first, then the scheduler (a worker whose scheduler is gone
# retries its connection instead of exiting); what has not exited 10 s
# after SIGTERM gets SIGKILL, so a slow shutdown never hangs the test.
stop() {
  local i pid alive
  for ((i = ${#pids[@]} - 1; i >= 0; i--)); do kill -TERM "${pids[i]}" 2> /dev/null || true; done
  for _ in $(seq 100); do
    alive=0
    for pid in "${pids[@]}"; do kill -0 "$pid" 2> /dev/null && alive=1; done
    [ "$alive" -eq 0 ] && break
    sleep 0.1
  done
  for pid in "${pids[@]}"; do kill -KILL "$pid" 2> /dev/null || true; done
  for pid in "${pids[@]}"; do wait "$pid" 2> /dev/null || true; done
  rm -rf "$dir"
}
trap stop EXIT
start=$SECONDS
export PYTHONPATH=$pythonpath PYTHONDONTWRITEBYTECODE=1
dask scheduler --host 127.0.0.1 --port 0 --no-dashboard --scheduler-file "$dir/sched.json" > "$dir/scheduler.log" 2>&1 &
pids+=($!)
for _ in $(seq 300); do [ -s "$dir/sched.json" ] && break; sleep 0.1; done
for w in 1 2; do
  dask worker --scheduler-file "$dir/sched.json" --nthreads 1 --no-nanny --no-dashboard --name "w$w" \
    --local-directory "$dir/w$w" > "$dir/worker_$w.log" 2>&1 &
  pids+=($!)
done
# Both workers registered before the work is handed out, so both get shards.
/usr/bin/python3 -c 'import sys; from distributed import Client; c = Client(scheduler_file=sys.argv[1], timeout=30); c.wait_for_workers(2, timeout=30); c.close()' "$dir/sched.json"
echo "scheduler and 2 workers up in $((SECONDS - start)) s"

grid=(--loads-gcm2 0,2000,6000,10000 --angles-deg 20,45 --speeds-dps 1500 --cycles 1)
"$bin" sweep "${grid[@]}" --threads 1 --csv "$dir/cli.csv" > /dev/null
/usr/bin/python3 "$example" --scheduler-file "$dir/sched.json" "${grid[@]}" --shards 4 --csv "$dir/dask.csv" \
  --sreh-twin "$bin" 2> "$dir/example.log" || { cat "$dir"/*.log >&2; exit 1; }
cat "$dir/example.log"
cmp "$dir/cli.csv" "$dir/dask.csv"
grep -q "^4 shards on 2 Dask workers" "$dir/example.log"
echo "Dask: 2 worker processes, the CLI's CSV byte for byte ($((SECONDS - start)) s)"
