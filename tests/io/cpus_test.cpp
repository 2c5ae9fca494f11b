// Default thread count (issue 31): the CPUs the process may use, or Slurm's grant.
#include <gtest/gtest.h>

#include <sched.h>

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>

#include "io/cpus.hpp"

namespace sreh::io {
namespace {

std::map<std::string, std::string> g_env;
const char* fake_env(const char* name) {
  const auto it = g_env.find(name);
  return it == g_env.end() ? nullptr : it->second.c_str();
}

int threads(std::map<std::string, std::string> env, int max = 64) {
  g_env = std::move(env);
  return default_threads(fake_env, max);
}

TEST(Cpus, FollowsTheAffinityMaskNotTheMachine) {
  cpu_set_t saved;
  ASSERT_EQ(sched_getaffinity(0, sizeof saved, &saved), 0);
  EXPECT_EQ(threads({}), std::min(64, CPU_COUNT(&saved)));
  // Confined to one CPU (as `srun -c1` with cgroups or `taskset -c 0` do): one thread.
  cpu_set_t one;
  CPU_ZERO(&one);
  for (int c = 0; c < CPU_SETSIZE; ++c) {
    if (CPU_ISSET(c, &saved)) {
      CPU_SET(c, &one);
      break;
    }
  }
  ASSERT_EQ(sched_setaffinity(0, sizeof one, &one), 0);
  EXPECT_EQ(usable_cpus(), 1);
  EXPECT_EQ(threads({}), 1);
  EXPECT_EQ(threads({{"SLURM_CPUS_PER_TASK", ""}}), 1); // set but empty: as unset
  EXPECT_EQ(threads({{"SLURM_CPUS_PER_TASK", "2"}}), 1); // srun bound the step to 1 CPU of the 2 granted
  ASSERT_EQ(sched_setaffinity(0, sizeof saved, &saved), 0);
}

TEST(Cpus, SlurmCpusPerTaskLimitsAndIsChecked) {
  const int cpus = usable_cpus();
  EXPECT_EQ(threads({{"SLURM_CPUS_PER_TASK", "1"}}), 1);
  EXPECT_EQ(threads({{"SLURM_CPUS_PER_TASK", "3"}}), std::min(3, cpus));
  EXPECT_EQ(threads({{"SLURM_CPUS_PER_TASK", "128"}}), std::min(64, cpus)); // never more than the CPUs, nor max
  EXPECT_EQ(threads({{"SLURM_CPUS_PER_TASK", "2"}}, 1), 1);
  for (const char* bad : {"0", "-2", "two", "2x", " 2"}) {
    try {
      threads({{"SLURM_CPUS_PER_TASK", bad}});
      ADD_FAILURE() << "accepted " << bad;
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()), std::string("SLURM_CPUS_PER_TASK=") + bad +
                                           ": expected a whole number >= 1 (the default of --threads)");
    }
  }
}

} // namespace
} // namespace sreh::io
