#!/bin/bash
# Issue 31: sharded sweeps and scenario folders on a real Slurm (one node on
# loopback, tests/slurm/one_node_cluster.sh), submitted with the recipe of
# docs/sizing.md (examples/slurm/sweep.sbatch): arrays 1-3 and 5-9:2, a
# rerun of one task of 1-3, the merge as a dependent job; every union is
# byte for byte the unsharded output. Exit 77 (CTest: skipped) only when
# Debian's slurm packages are not installed (./setup.sh installs them) or
# the machine has no cgroup filesystem for slurmd (a chroot without /sys).
#   slurm_check.sh SREH_TWIN SWEEP_SBATCH SCENARIO_FOLDER
set -euo pipefail
bin=$(realpath "$1")
sbatch_file=$(realpath "$2")
folder=$(realpath "$3")
here=$(dirname "$(realpath "$0")")
. "$here/one_node_cluster.sh"
missing=$(slurm_packages_missing)
if [ -n "$missing" ]; then
  echo "skipped: no $missing(Debian's slurmctld slurmd slurm-client munge; ./setup.sh installs them)"
  exit 77
fi
# Debian 12's slurmd (Slurm 22.05) starts its cgroup plugin even with
# proctrack/linuxproc and task/none, and refuses to run without a cgroup
# filesystem: a chroot without /sys (a bare debootstrap root entered with
# only /proc mounted) cannot host it, whatever this project does.
if [ -z "$(ls -A /sys/fs/cgroup 2> /dev/null)" ]; then
  echo "skipped: no cgroup filesystem in /sys/fs/cgroup, which slurmd needs (for a chroot, bind the host's first: mount --rbind /sys ROOT/sys)"
  exit 77
fi
dir=$(mktemp -d)
trap 'slurm_stop; rm -rf "$dir"' EXIT
start=$SECONDS
slurm_start "$dir/cluster"
echo "cluster up in $((SECONDS - start)) s"
PATH="$(dirname "$bin"):$PATH" # the recipe calls `sreh-twin`
export PATH

grid=(--loads-gcm2 0,2000,6000 --angles-deg 20,45 --speeds-dps 1500 --cycles 1)
sreh-twin sweep "${grid[@]}" --threads 1 --csv "$dir/whole.csv" > /dev/null
sreh-twin run "$folder" --json > "$dir/whole.jsonl" || test $? -eq 1 # one file fails on purpose
mkdir "$dir/a1-3" "$dir/a5-9" "$dir/rerun" "$dir/run"
submit() { # submit FOLDER SBATCH-ARGS...: prints the job id
  (cd "$1" && shift && sbatch --parsable --cpus-per-task=1 "$@")
}
j13=$(submit "$dir/a1-3" --array=1-3 "$sbatch_file" "${grid[@]}")
submit "$dir/a1-3" --dependency=afterok:"$j13" --kill-on-invalid-dep=yes --output=merge.log \
  --wrap 'sreh-twin sweep merge --csv sweep.csv part_*.csv' > /dev/null
submit "$dir/a5-9" --array=5-9:2 "$sbatch_file" "${grid[@]}" > /dev/null
submit "$dir/rerun" --array=2 --export=ALL,SHARDS=3 "$sbatch_file" "${grid[@]}" > /dev/null
submit "$dir/run" --array=5-9:2 --output=run_%a.log \
  --wrap "sreh-twin run $folder --json --shard auto > run_\$SLURM_ARRAY_TASK_ID.jsonl" > /dev/null
slurm_wait 60 "an empty queue" bash -c '[ -z "$(squeue -h -o %i)" ]'
echo "jobs done in $((SECONDS - start)) s"
show() { tail -n 5 "$dir"/*/*.log >&2; }
trap 'show; slurm_stop; rm -rf "$dir"' ERR

# The threads came from --cpus-per-task (SLURM_CPUS_PER_TASK=1); the shard lines from the array.
for i in 1 2 3; do
  grep -qx "2 points, 2 feasible, 1 thread: part_$i.csv" "$dir/a1-3/sweep_$i.log"
  grep -qx "# sreh-twin sweep shard $i/3 rows 2 of 6" "$dir/a1-3/part_$i.csv"
done
cmp "$dir/whole.csv" "$dir/a1-3/sweep.csv" # merged by the dependent job
grep -q "^3 parts merged" "$dir/a1-3/merge.log"
sreh-twin sweep merge --csv "$dir/a5-9/sweep.csv" "$dir"/a5-9/part_*.csv > /dev/null
cmp "$dir/whole.csv" "$dir/a5-9/sweep.csv"
cmp "$dir/a1-3/part_2.csv" "$dir/rerun/part_2.csv" # the rerun recomputed exactly shard 2/3
sreh-twin sweep merge --csv "$dir/rerun/sweep.csv" "$dir/a1-3/part_1.csv" "$dir/rerun/part_2.csv" \
  "$dir/a1-3/part_3.csv" > /dev/null
cmp "$dir/whole.csv" "$dir/rerun/sweep.csv"
cat "$dir"/run/run_5.jsonl "$dir"/run/run_7.jsonl "$dir"/run/run_9.jsonl > "$dir/run/union.jsonl"
cmp "$dir/whole.jsonl" "$dir/run/union.jsonl"
echo "Slurm arrays 1-3, 5-9:2 and a one-task rerun merge byte-identical ($((SECONDS - start)) s)"
