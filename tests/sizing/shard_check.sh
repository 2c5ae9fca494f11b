#!/bin/bash
# Issues 17, 31: `sweep --shard i/N` parts, run in parallel by GNU parallel and
# joined with `sweep merge`, give the unsharded CSV byte for byte; --shard
# auto (Slurm array) and auto/N (Kubernetes indexed Job) pick the same blocks.
set -euo pipefail
bin=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
grid=(--loads-gcm2 0,2000,6000 --angles-deg 20,45 --speeds-dps 1500 --cycles 1 --threads 1)
"$bin" sweep "${grid[@]}" --csv "$dir/whole.csv" > /dev/null
parallel --halt now,fail=1 "$bin" sweep "${grid[@]}" --shard {}/4 --csv "$dir/part_{}.csv" ::: 1 2 3 4 > /dev/null
"$bin" sweep merge --csv "$dir/merged.csv" "$dir"/part_4.csv "$dir"/part_2.csv "$dir"/part_1.csv "$dir"/part_3.csv > /dev/null
cmp "$dir/whole.csv" "$dir/merged.csv"
# Slurm: array 5-8 -> shards 1..4, array 3-12:3 -> the same (issue 31: the
# step); Kubernetes: indexes 0..3.
for id in 5 6 7 8; do
  SLURM_ARRAY_TASK_ID=$id SLURM_ARRAY_TASK_MIN=5 SLURM_ARRAY_TASK_MAX=8 SLURM_ARRAY_TASK_STEP=1 SLURM_ARRAY_TASK_COUNT=4 \
    "$bin" sweep "${grid[@]}" --shard auto --csv "$dir/slurm_$id.csv" > /dev/null
  cmp "$dir/slurm_$id.csv" "$dir/part_$((id - 4)).csv"
done
for id in 3 6 9 12; do
  SLURM_ARRAY_TASK_ID=$id SLURM_ARRAY_TASK_MIN=3 SLURM_ARRAY_TASK_MAX=12 SLURM_ARRAY_TASK_STEP=3 SLURM_ARRAY_TASK_COUNT=4 \
    "$bin" sweep "${grid[@]}" --shard auto --csv "$dir/step_$id.csv" > /dev/null
  cmp "$dir/step_$id.csv" "$dir/part_$((id / 3)).csv"
done
# --array=1,2,4 is refused (exit 2, why and what to use), nothing written.
status=0
SLURM_ARRAY_TASK_ID=4 SLURM_ARRAY_TASK_MIN=1 SLURM_ARRAY_TASK_MAX=4 SLURM_ARRAY_TASK_STEP=1 SLURM_ARRAY_TASK_COUNT=3 \
  "$bin" sweep "${grid[@]}" --shard auto --csv "$dir/never.csv" 2> "$dir/err" || status=$?
test "$status" -eq 2
grep -q "^sreh-twin: --shard auto: Slurm array 1-4:1 with 3 tasks (task 4): the ids are not an arithmetic sequence.*--array=FIRST-LAST\[:STEP\] or give each task --shard i/N" "$dir/err"
test ! -e "$dir/never.csv"
# One part (1/1, or a one-task array) has its shard line and merges alone
# into the unsharded CSV (issue 31).
"$bin" sweep "${grid[@]}" --shard 1/1 --csv "$dir/one.csv" > /dev/null
head -1 "$dir/one.csv" | grep -qx "# sreh-twin sweep shard 1/1 rows 6 of 6"
"$bin" sweep merge --csv "$dir/one_merged.csv" "$dir/one.csv" > /dev/null
cmp "$dir/whole.csv" "$dir/one_merged.csv"
SLURM_ARRAY_TASK_ID=7 SLURM_ARRAY_TASK_MIN=7 SLURM_ARRAY_TASK_MAX=7 SLURM_ARRAY_TASK_STEP=1 SLURM_ARRAY_TASK_COUNT=1 \
  "$bin" sweep "${grid[@]}" --shard auto --csv "$dir/one_task.csv" > /dev/null 2> "$dir/note"
cmp "$dir/one.csv" "$dir/one_task.csv"
# ... with a note, since that is also what `sbatch --array=7` of a larger array looks like.
grep -qx "sreh-twin: note: --shard auto: a one-task Slurm array (task 7) is shard 1/1, the whole batch; to rerun task 7 of an array 1-N give --shard 7/N" "$dir/note"
# The rerun form for one task of an array 1-4: --shard $SLURM_ARRAY_TASK_ID/4.
SLURM_ARRAY_TASK_ID=3 SLURM_ARRAY_TASK_MIN=3 SLURM_ARRAY_TASK_MAX=3 SLURM_ARRAY_TASK_STEP=1 SLURM_ARRAY_TASK_COUNT=1 \
  bash -c '"$0" sweep "${@}" --shard "$SLURM_ARRAY_TASK_ID/4" --csv "'"$dir"'/rerun.csv"' "$bin" "${grid[@]}" > /dev/null
cmp "$dir/rerun.csv" "$dir/part_3.csv"
JOB_COMPLETION_INDEX=2 "$bin" sweep "${grid[@]}" --shard auto/4 --csv "$dir/k8s.csv" > /dev/null
cmp "$dir/k8s.csv" "$dir/part_3.csv"
# A missing part is refused (exit 2), nothing written.
if "$bin" sweep merge --csv "$dir/bad.csv" "$dir"/part_1.csv "$dir"/part_2.csv 2> "$dir/err"; then exit 1; fi
grep -q "shard 3/4 is missing" "$dir/err"
test ! -e "$dir/bad.csv"
echo "shards merge byte-identical"
