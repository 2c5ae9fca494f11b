#!/bin/bash
# Issue 17: `run DIR --shard i/N` parts, run in parallel by GNU parallel,
# together run every file of the folder exactly once: the concatenated
# JSON Lines of shards 1..N are byte for byte those of the unsharded run
# (files sorted, contiguous blocks); --shard auto (Slurm array) and auto/N
# (Kubernetes indexed Job) pick the same blocks; exit codes per shard.
set -euo pipefail
bin=$1
folder=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
status=0
"$bin" run "$folder" --json > "$dir/whole.jsonl" || status=$?
test "$status" -eq 1 # one file fails on purpose
test "$(wc -l < "$dir/whole.jsonl")" -eq 5
for n in 1 2 3 5 7; do
  parallel --halt never "$bin" run "$folder" --json --shard {}/$n '>' "$dir/part_{}_of_$n.jsonl" ::: $(seq 1 $n) || true
  for i in $(seq 1 $n); do cat "$dir/part_${i}_of_$n.jsonl"; done > "$dir/union_$n.jsonl"
  cmp "$dir/whole.jsonl" "$dir/union_$n.jsonl"
done
# Exit codes per shard of 3 (blocks a | b c | d e: c_fails is in shard 2).
"$bin" run "$folder" --shard 1/3 > /dev/null
if "$bin" run "$folder" --shard 2/3 > /dev/null; then exit 1; fi
# More shards than files: a shard with none runs nothing and holds.
"$bin" run "$folder" --shard 1/7 > "$dir/none.txt" # block [0, 5/7) of 5: empty
grep -q "0 of 0 scenarios held" "$dir/none.txt"
# Slurm: array 5-7 and 5-9:2 -> shards 1..3 (issue 31); Kubernetes: indexes 0..2.
for id in 5 6 7; do
  SLURM_ARRAY_TASK_ID=$id SLURM_ARRAY_TASK_MIN=5 SLURM_ARRAY_TASK_MAX=7 SLURM_ARRAY_TASK_STEP=1 SLURM_ARRAY_TASK_COUNT=3 \
    "$bin" run "$folder" --json --shard auto > "$dir/slurm_$id.jsonl" || true
  cmp "$dir/slurm_$id.jsonl" "$dir/part_$((id - 4))_of_3.jsonl"
  step_id=$((2 * id - 5))
  SLURM_ARRAY_TASK_ID=$step_id SLURM_ARRAY_TASK_MIN=5 SLURM_ARRAY_TASK_MAX=9 SLURM_ARRAY_TASK_STEP=2 SLURM_ARRAY_TASK_COUNT=3 \
    "$bin" run "$folder" --json --shard auto > "$dir/step_$step_id.jsonl" || true
  cmp "$dir/step_$step_id.jsonl" "$dir/part_$((id - 4))_of_3.jsonl"
  JOB_COMPLETION_INDEX=$((id - 5)) "$bin" run "$folder" --json --shard auto/3 > "$dir/k8s_$id.jsonl" || true
  cmp "$dir/k8s_$id.jsonl" "$dir/part_$((id - 4))_of_3.jsonl"
done
# An array that is not an arithmetic sequence (--array=1,2,4) is refused.
status=0
SLURM_ARRAY_TASK_ID=2 SLURM_ARRAY_TASK_MIN=1 SLURM_ARRAY_TASK_MAX=4 SLURM_ARRAY_TASK_STEP=1 SLURM_ARRAY_TASK_COUNT=3 \
  "$bin" run "$folder" --shard auto > "$dir/out" 2> "$dir/err" || status=$?
test "$status" -eq 2
test ! -s "$dir/out"
grep -q "not an arithmetic sequence" "$dir/err"
# A one-task array runs the whole folder and names the rerun form.
SLURM_ARRAY_TASK_ID=2 SLURM_ARRAY_TASK_MIN=2 SLURM_ARRAY_TASK_MAX=2 SLURM_ARRAY_TASK_STEP=1 SLURM_ARRAY_TASK_COUNT=1 \
  "$bin" run "$folder" --json --shard auto > "$dir/one_task.jsonl" 2> "$dir/err" || true
cmp "$dir/whole.jsonl" "$dir/one_task.jsonl"
grep -q "to rerun task 2 of an array 1-N give --shard 2/N" "$dir/err"
# The text lines name the same files in the same order.
"$bin" run "$folder" > "$dir/whole.txt" || true
grep -oE '^(PASS|FAIL)  [^ ]+' "$dir/whole.txt" | awk '{print $2}' > "$dir/text_files"
/usr/bin/python3 -c 'import json,sys; [print(json.loads(l)["file"]) for l in open(sys.argv[1])]' "$dir/whole.jsonl" > "$dir/json_files"
cmp "$dir/text_files" "$dir/json_files"
echo "folder shards cover every file once, byte-identical"
