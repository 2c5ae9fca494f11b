// Splitting a batch over the tasks of a job array (issues 17, 31; A-SIZE-11, A-SHARD-1, A-SHARD-2):
// `sweep --shard` (grid points) and `run DIR --shard` (scenario files) share
// this one parser and one split.
#pragma once
#include <cstddef>
#include <string>
#include <utility>

namespace sreh::io {

// "i/N", "auto" (Slurm array: i = (SLURM_ARRAY_TASK_ID - SLURM_ARRAY_TASK_MIN)
// / SLURM_ARRAY_TASK_STEP + 1, N = SLURM_ARRAY_TASK_COUNT; refused unless the
// array's ids are MIN, MIN + STEP, ..., MAX) or "auto/N" (Kubernetes indexed
// Job: i = JOB_COMPLETION_INDEX + 1), 1 <= i <= N <= 100000. Rerunning one
// task of an array 1-N: "$SLURM_ARRAY_TASK_ID/N" (a one-task array is 1/1 to
// "auto"). `env` looks a variable up (nullptr: unset). Throws
// std::invalid_argument naming --shard and the value.
std::pair<std::size_t, std::size_t> parse_shard(const std::string& text, const char* (*env)(const char*));

// For "auto" in a one-task Slurm array, which is shard 1/1 (the whole
// batch): a note naming the rerun form, since `sbatch --array=ID` is how one
// failed task of a larger array is rerun. "" otherwise.
std::string one_task_array_note(const std::string& text, const char* (*env)(const char*));

// The items of shard i of N among `total` (1-based i): the contiguous block
// [floor((i-1) total / N), floor(i total / N)); the N blocks cover every item once.
std::pair<std::size_t, std::size_t> shard_range(std::size_t shard, std::size_t shards, std::size_t total);

} // namespace sreh::io
