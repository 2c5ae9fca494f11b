#!/bin/bash
# Issue 31: `--threads` and its default from Slurm fail naming the value,
# exit 2, one line, nothing written; set-but-empty SLURM_CPUS_PER_TASK is as unset.
set -euo pipefail
bin=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
grid=(--loads-gcm2 0 --angles-deg 20 --speeds-dps 1500 --cycles 1)
refused() { # refused REGEX COMMAND...: exit 2, one line on stderr matching REGEX, no CSV
  local re=$1 status=0
  shift
  "$@" > "$dir/out" 2> "$dir/err" || status=$?
  test "$status" -eq 2 || { echo "exit $status: $*" >&2; cat "$dir/err" >&2; exit 1; }
  test "$(wc -l < "$dir/err")" -eq 1
  grep -qE "$re" "$dir/err" || { echo "stderr does not match $re:" >&2; cat "$dir/err" >&2; exit 1; }
  test ! -e "$dir/out.csv"
}
# The docs' old `--threads "$SLURM_CPUS_PER_TASK"` without --cpus-per-task.
refused "^sreh-twin: --threads: '' is not a whole number 1 \.\. 64 \(an unset variable such as SLURM_CPUS_PER_TASK\? leave --threads out" \
  "$bin" sweep "${grid[@]}" --threads "" --csv "$dir/out.csv"
refused "^sreh-twin: --threads: '0' is not a whole number 1 \.\. 64$" "$bin" sweep "${grid[@]}" --threads 0 --csv "$dir/out.csv"
refused "^sreh-twin: --threads: '65' is not a whole number 1 \.\. 64$" "$bin" sweep "${grid[@]}" --threads 65 --csv "$dir/out.csv"
refused "^sreh-twin: --threads: 'two' is not a whole number" "$bin" sweep "${grid[@]}" --threads two --csv "$dir/out.csv"
refused "^sreh-twin: SLURM_CPUS_PER_TASK=x2: expected a whole number >= 1 \(the default of --threads\)$" \
  env SLURM_CPUS_PER_TASK=x2 "$bin" sweep "${grid[@]}" --csv "$dir/out.csv"
# The default: the CPUs this process may use (one under taskset), not the
# machine's, and fewer if SLURM_CPUS_PER_TASK says so; set but empty is as
# unset; --threads given: the variable is not read.
cpus=$(nproc) # the affinity mask, as sched_getaffinity
threads() { # threads N COMMAND...: the run says it used N threads
  local n=$1
  shift
  "$@" > "$dir/out"
  grep -qE "^1 points, 1 feasible, $n threads?: " "$dir/out" || { echo "expected $n threads: $*" >&2; cat "$dir/out" >&2; exit 1; }
}
threads 1 taskset -c 0 "$bin" sweep "${grid[@]}" --csv "$dir/a.csv"
threads "$cpus" env -u SLURM_CPUS_PER_TASK "$bin" sweep "${grid[@]}" --csv "$dir/b.csv"
threads "$cpus" env SLURM_CPUS_PER_TASK= "$bin" sweep "${grid[@]}" --csv "$dir/c.csv"
threads 1 env SLURM_CPUS_PER_TASK=1 "$bin" sweep "${grid[@]}" --csv "$dir/d.csv"
threads 1 env SLURM_CPUS_PER_TASK=3 taskset -c 0 "$bin" sweep "${grid[@]}" --csv "$dir/f.csv" # never more than the CPUs
threads 1 env SLURM_CPUS_PER_TASK=x2 "$bin" sweep "${grid[@]}" --threads 1 --csv "$dir/e.csv"
for f in b c d e f; do cmp "$dir/a.csv" "$dir/$f.csv"; done
echo "threads: errors name the value"
