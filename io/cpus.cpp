#include "io/cpus.hpp"

#include <sched.h>

#include <algorithm>
#include <charconv>
#include <stdexcept>
#include <string>
#include <string_view>

#include "io/text.hpp"

namespace sreh::io {

int usable_cpus() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) != 0) return 1; // more than CPU_SETSIZE CPUs: one thread is safe
  return std::max(1, CPU_COUNT(&set));
}

int default_threads(const char* (*env)(const char*), int max) {
  const char* slurm = env("SLURM_CPUS_PER_TASK");
  if (slurm == nullptr || *slurm == '\0') return std::clamp(usable_cpus(), 1, max);
  const std::string_view s(slurm);
  long long n = 0;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), n);
  if (r.ec != std::errc() || r.ptr != s.data() + s.size() || n < 1) {
    throw std::invalid_argument("SLURM_CPUS_PER_TASK=" + escape_control(s) +
                                ": expected a whole number >= 1 (the default of --threads)");
  }
  // Never more than the CPUs we may run on: Slurm 22.05's srun no longer
  // passes --cpus-per-task on to the step, which then runs bound to 1 CPU.
  return static_cast<int>(std::min<long long>({n, usable_cpus(), max}));
}

} // namespace sreh::io
