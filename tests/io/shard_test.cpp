// --shard (issue 17): one parser and one split for `sweep` and `run DIR`.
#include <gtest/gtest.h>

#include <cstring>
#include <map>
#include <stdexcept>
#include <string>

#include "io/shard.hpp"

namespace sreh::io {
namespace {

std::map<std::string, std::string> g_shard_env;
const char* fake_shard_env(const char* name) {
  const auto it = g_shard_env.find(name);
  return it == g_shard_env.end() ? nullptr : it->second.c_str();
}

std::pair<std::size_t, std::size_t> parse(const std::string& text, std::map<std::string, std::string> env = {}) {
  g_shard_env = std::move(env);
  return parse_shard(text, fake_shard_env);
}

// The variables Slurm 22.05 sets in every task of an array (checked on a real one in tests/slurm).
std::map<std::string, std::string> slurm(int id, int min, int max, int step, int count) {
  return {{"SLURM_ARRAY_TASK_ID", std::to_string(id)},    {"SLURM_ARRAY_TASK_MIN", std::to_string(min)},
          {"SLURM_ARRAY_TASK_MAX", std::to_string(max)},  {"SLURM_ARRAY_TASK_STEP", std::to_string(step)},
          {"SLURM_ARRAY_TASK_COUNT", std::to_string(count)}};
}

std::string error_of(const std::string& text, std::map<std::string, std::string> env) {
  try {
    parse(text, std::move(env));
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(accepted)";
}

// The error for `text` in `env` contains `part`.
bool says(const std::string& text, std::map<std::string, std::string> env, const std::string& part) {
  return error_of(text, std::move(env)).find(part) != std::string::npos;
}

TEST(Shard, ParsesExplicitSlurmAndKubernetesForms) {
  EXPECT_EQ(parse("2/5"), std::make_pair(std::size_t{2}, std::size_t{5}));
  EXPECT_EQ(parse("1/1"), std::make_pair(std::size_t{1}, std::size_t{1}));
  // Slurm array 5-8: task 7 is shard 3 of 4.
  EXPECT_EQ(parse("auto", slurm(7, 5, 8, 1, 4)), std::make_pair(std::size_t{3}, std::size_t{4}));
  // Kubernetes indexed Job: index 0 is shard 1.
  EXPECT_EQ(parse("auto/3", {{"JOB_COMPLETION_INDEX", "0"}}), std::make_pair(std::size_t{1}, std::size_t{3}));
}

TEST(Shard, RefusesBadTextsNamingTheOption) {
  for (const char* bad : {"", "3", "0/4", "5/4", "-1/4", "1/0", "a/b", "1/4x", " 1/4", "auto/", "auto/x", "1/100001"}) {
    try {
      parse(bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()).rfind("--shard ", 0), 0u) << e.what();
    }
  }
  EXPECT_THROW(parse("auto"), std::invalid_argument);                                 // not in a Slurm array
  EXPECT_THROW(parse("auto/2", {{"JOB_COMPLETION_INDEX", "2"}}), std::invalid_argument); // index 2 of 2: shard 3
  EXPECT_THROW(parse("auto/2", {{"JOB_COMPLETION_INDEX", "x"}}), std::invalid_argument);
  // Echoed values stay one line.
  try {
    parse("1/\n2");
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::strchr(e.what(), '\n'), nullptr);
  }
}

TEST(Shard, SlurmArrayWithAStepGivesEveryShardOnce) {
  // Issue 31: --array=5-9:2 is ids 5, 7, 9: shards 1, 2, 3 of 3 (it was 1, 2 and "5 is outside 1 .. 3").
  for (const auto& [id, shard] : {std::pair{5, 1}, {7, 2}, {9, 3}}) {
    EXPECT_EQ(parse("auto", slurm(id, 5, 9, 2, 3)), std::make_pair(std::size_t(shard), std::size_t{3})) << id;
  }
  EXPECT_EQ(parse("auto", slurm(1, 1, 5, 2, 3)), std::make_pair(std::size_t{1}, std::size_t{3}));
  EXPECT_EQ(parse("auto", slurm(0, 0, 0, 1, 1)), std::make_pair(std::size_t{1}, std::size_t{1})); // a one-task array
  // The rerun form for one task of an array 1-N: its own id over the fixed N.
  EXPECT_EQ(parse("2/3", slurm(2, 2, 2, 1, 1)), std::make_pair(std::size_t{2}, std::size_t{3}));
}

TEST(Shard, OneTaskArrayNamesTheRerunForm) {
  g_shard_env = slurm(2, 2, 2, 1, 1); // sbatch --array=2
  EXPECT_EQ(one_task_array_note("auto", fake_shard_env),
            "note: --shard auto: a one-task Slurm array (task 2) is shard 1/1, the whole batch; to rerun task 2 of "
            "an array 1-N give --shard 2/N");
  EXPECT_EQ(one_task_array_note("2/3", fake_shard_env), "");
  g_shard_env = slurm(2, 1, 3, 1, 3);
  EXPECT_EQ(one_task_array_note("auto", fake_shard_env), "");
  g_shard_env = {};
  EXPECT_EQ(one_task_array_note("auto", fake_shard_env), "");
}

TEST(Shard, RefusesSlurmArraysThatAreNotArithmetic) {
  // --array=1,2,4: min 1, max 4, 3 tasks; no step makes 1, 1+s, 1+2s = 4.
  for (int step : {1, 2, 3}) {
    for (int id : {1, 2, 4}) {
      const std::string e = error_of("auto", slurm(id, 1, 4, step, 3));
      EXPECT_NE(e.find("--shard auto: Slurm array 1-4:" + std::to_string(step) + " with 3 tasks (task " +
                       std::to_string(id) + "): the ids are not an arithmetic sequence"),
                std::string::npos)
          << e;
      EXPECT_NE(e.find("--array=FIRST-LAST[:STEP] or give each task --shard i/N"), std::string::npos) << e;
    }
  }
  EXPECT_TRUE(says("auto", slurm(6, 5, 9, 2, 3), "not an arithmetic sequence")); // off the step
  EXPECT_TRUE(says("auto", slurm(11, 5, 9, 2, 3), "not an arithmetic sequence")); // past max
  EXPECT_TRUE(says("auto", slurm(5, 5, 9, 0, 3), "not an arithmetic sequence"));
  // Each variable is needed, and named when missing or not a number.
  for (const char* name : {"SLURM_ARRAY_TASK_ID", "SLURM_ARRAY_TASK_MIN", "SLURM_ARRAY_TASK_MAX",
                           "SLURM_ARRAY_TASK_STEP", "SLURM_ARRAY_TASK_COUNT"}) {
    auto env = slurm(5, 5, 9, 2, 3);
    env.erase(name);
    EXPECT_EQ(error_of("auto", env), std::string("--shard auto: ") + name + " is not set");
    env[name] = "7x";
    EXPECT_EQ(error_of("auto", env), std::string("--shard auto: ") + name + "=7x is not an integer");
  }
  EXPECT_TRUE(says("auto", slurm(5, 5, 9, 2, 0), "SLURM_ARRAY_TASK_COUNT = 0 is outside 1 .. 100000"));
  EXPECT_TRUE(says("auto", slurm(-1, -1, 1, 1, 3), "not a Slurm array"));
  auto huge = slurm(5, 5, 9, 2, 3);
  huge["SLURM_ARRAY_TASK_MAX"] = "9223372036854775807"; // no overflow in the checks
  EXPECT_TRUE(says("auto", huge, "not a Slurm array"));
  EXPECT_TRUE(says("auto/3", {{"JOB_COMPLETION_INDEX", "9223372036854775807"}}, "is outside 0 .. N-1 = 2"));
}

TEST(Shard, BlocksCoverEveryItemOnceInOrder) {
  for (std::size_t total : {0u, 1u, 5u, 7u, 100u}) {
    for (std::size_t n : {1u, 2u, 3u, 8u}) {
      std::size_t next = 0;
      for (std::size_t i = 1; i <= n; ++i) {
        const auto [begin, end] = shard_range(i, n, total);
        EXPECT_EQ(begin, next);
        EXPECT_LE(end - begin, total / n + 1); // balanced
        next = end;
      }
      EXPECT_EQ(next, total);
    }
  }
}

} // namespace
} // namespace sreh::io
