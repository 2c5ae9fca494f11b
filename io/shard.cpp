#include "io/shard.hpp"

#include <charconv>
#include <optional>
#include <stdexcept>
#include <string_view>

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

} // namespace

std::pair<std::size_t, std::size_t> parse_shard(const std::string& text, const char* (*env)(const char*)) {
  long long i = 0, n = 0;
  if (text == "auto") { // Slurm job array
    i = env_int(env, "SLURM_ARRAY_TASK_ID", text) - env_int(env, "SLURM_ARRAY_TASK_MIN", text) + 1;
    n = env_int(env, "SLURM_ARRAY_TASK_COUNT", text);
  } else if (text.rfind("auto/", 0) == 0) { // Kubernetes indexed Job
    const auto count = to_int(std::string_view(text).substr(5));
    if (!count) throw bad(text, "expected auto/N with an integer N");
    n = *count;
    i = env_int(env, "JOB_COMPLETION_INDEX", text) + 1;
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

std::pair<std::size_t, std::size_t> shard_range(std::size_t shard, std::size_t shards, std::size_t total) {
  return {(shard - 1) * total / shards, shard * total / shards};
}

} // namespace sreh::io
