// How many worker threads a batch job should start by default (issue 31, A-SHARD-3):
// the CPUs this process may run on, not the machine's cores. Inside
// `srun -c1`, a `taskset` or a container's cpuset, hardware_concurrency()
// still counts every core of the node (64 on a big one) and oversubscribes.
#pragma once

namespace sreh::io {

// The CPUs in this process's affinity mask (sched_getaffinity), and fewer
// if SLURM_CPUS_PER_TASK is set and non-empty (Slurm's grant for this task,
// where Slurm does not bind tasks to CPUs); at least 1, at most `max`.
// `env` looks a variable up (nullptr: unset). Throws std::invalid_argument
// naming the variable and its value if it is not a whole number >= 1.
int default_threads(const char* (*env)(const char*), int max);

// The CPUs in this process's affinity mask (>= 1).
int usable_cpus();

} // namespace sreh::io
