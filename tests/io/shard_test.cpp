// --shard (issue 17): one parser and one split for `sweep` and `run DIR`.
#include <gtest/gtest.h>

#include <cstring>
#include <map>
#include <stdexcept>
#include <string>

#include "io/shard.hpp"

namespace sreh::io {
namespace {

std::map<std::string, std::string> g_env;
const char* fake_env(const char* name) {
  const auto it = g_env.find(name);
  return it == g_env.end() ? nullptr : it->second.c_str();
}

std::pair<std::size_t, std::size_t> parse(const std::string& text, std::map<std::string, std::string> env = {}) {
  g_env = std::move(env);
  return parse_shard(text, fake_env);
}

TEST(Shard, ParsesExplicitSlurmAndKubernetesForms) {
  EXPECT_EQ(parse("2/5"), std::make_pair(std::size_t{2}, std::size_t{5}));
  EXPECT_EQ(parse("1/1"), std::make_pair(std::size_t{1}, std::size_t{1}));
  // Slurm array 5-8: task 7 is shard 3 of 4.
  EXPECT_EQ(parse("auto", {{"SLURM_ARRAY_TASK_ID", "7"}, {"SLURM_ARRAY_TASK_MIN", "5"}, {"SLURM_ARRAY_TASK_COUNT", "4"}}),
            std::make_pair(std::size_t{3}, std::size_t{4}));
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
