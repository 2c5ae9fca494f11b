#include "io/shard.hpp"

#include <charconv>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <tuple>

#include "io/text.hpp"

namespace sreh::io {
namespace {

std::optional<long long> to_int(std::string_view s) {
  long long v = 0;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  if (r.ec != std::errc() || r.ptr != s.data() + s.size() || s.empty()) return std::nullopt;
  return v;
}

std::invalid_argument bad(const std::string& text, const std::string& why) {
  return std::invalid_argument("--shard " + escape_control(text) + ": " + why);
}

long long env_int(const char* (*env)(const char*), const char* name, const std::string& text) {
  const char* v = env(name);
  if (v == nullptr) throw bad(text, std::string(name) + " is not set");
  const auto n = to_int(v);
  if (!n) throw bad(text, std::string(name) + "=" + escape_control(v) + " is not an integer");
  return *n;
}

// Task ID's place in a Slurm array (issue 31): --array=5-9:2 runs ids 5, 7, 9
// as shards 1, 2, 3. Only an arithmetic sequence of ids says which place an
// id has without seeing the others: --array=1,2,4 (Slurm reports step 1)
// would compute shard 4 of 3 on task 4 and never shard 3, so it is refused.
constexpr long long kMaxSlurmId = 4294967295; // Slurm's ids are 32-bit; keeps the checks below exact

std::pair<long long, long long> slurm_array_shard(const char* (*env)(const char*), const std::string& text) {
  const long long id = env_int(env, "SLURM_ARRAY_TASK_ID", text);
  const long long min = env_int(env, "SLURM_ARRAY_TASK_MIN", text);
  const long long max = env_int(env, "SLURM_ARRAY_TASK_MAX", text);
  const long long step = env_int(env, "SLURM_ARRAY_TASK_STEP", text);
  const long long count = env_int(env, "SLURM_ARRAY_TASK_COUNT", text);
  const std::string array = "Slurm array " + std::to_string(min) + "-" + std::to_string(max) + ":" +
                            std::to_string(step) + " with " + std::to_string(count) + " tasks";
  if (count < 1 || count > 100000) {
    throw bad(text, "N = SLURM_ARRAY_TASK_COUNT = " + std::to_string(count) + " is outside 1 .. 100000");
  }
  for (const long long v : {id, min, max, step}) {
    if (v < 0 || v > kMaxSlurmId) throw bad(text, array + " (task " + std::to_string(id) + "): not a Slurm array");
  }
  if (step < 1 || max < min || max - min != (count - 1) * step || id < min || id > max ||
      (id - min) % step != 0) {
    throw bad(text, array + " (task " + std::to_string(id) +
                        "): the ids are not an arithmetic sequence, so a task cannot tell its shard; submit "
                        "--array=FIRST-LAST[:STEP] or give each task --shard i/N");
  }
  return {(id - min) / step + 1, count};
}

} // namespace

std::pair<std::size_t, std::size_t> parse_shard(const std::string& text, const char* (*env)(const char*)) {
  long long i = 0, n = 0;
  if (text == "auto") { // Slurm job array
    std::tie(i, n) = slurm_array_shard(env, text);
  } else if (text.rfind("auto/", 0) == 0) { // Kubernetes indexed Job
    const auto count = to_int(std::string_view(text).substr(5));
    if (!count) throw bad(text, "expected auto/N with an integer N");
    n = *count;
    const long long index = env_int(env, "JOB_COMPLETION_INDEX", text);
    if (index < 0 || index >= n) {
      throw bad(text, "JOB_COMPLETION_INDEX=" + std::to_string(index) + " is outside 0 .. N-1 = " +
                          std::to_string(n - 1));
    }
    i = index + 1;
  } else {
    const auto slash = text.find('/');
    const auto a = slash == std::string::npos ? std::nullopt : to_int(std::string_view(text).substr(0, slash));
    const auto b = slash == std::string::npos ? std::nullopt : to_int(std::string_view(text).substr(slash + 1));
    if (!a || !b) throw bad(text, "expected i/N, auto or auto/N");
    i = *a;
    n = *b;
  }
  if (n < 1 || n > 100000) throw bad(text, "N = " + std::to_string(n) + " is outside 1 .. 100000");
  if (i < 1 || i > n) throw bad(text, "shard " + std::to_string(i) + " is outside 1 .. " + std::to_string(n));
  return {static_cast<std::size_t>(i), static_cast<std::size_t>(n)};
}

std::string one_task_array_note(const std::string& text, const char* (*env)(const char*)) {
  const char* count = env("SLURM_ARRAY_TASK_COUNT");
  const char* id = env("SLURM_ARRAY_TASK_ID");
  if (text != "auto" || count == nullptr || std::string_view(count) != "1" || id == nullptr) return "";
  const std::string i = escape_control(id);
  return "note: --shard auto: a one-task Slurm array (task " + i +
         ") is shard 1/1, the whole batch; to rerun task " + i + " of an array 1-N give --shard " + i + "/N";
}

std::pair<std::size_t, std::size_t> shard_range(std::size_t shard, std::size_t shards, std::size_t total) {
  return {(shard - 1) * total / shards, shard * total / shards};
}

} // namespace sreh::io
