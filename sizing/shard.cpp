// Sharding a sweep over machines (issue 17, A-SIZE-11): joining the parts
// back into the unsharded CSV byte for byte (which block a task runs: io/shard).
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "io/shard.hpp"
#include "sizing/sweep.hpp"

namespace sreh::sizing {
namespace {

constexpr const char* kMarker = "# sreh-twin sweep shard ";

} // namespace

std::string shard_marker(const SweepResult& r) {
  return fmt::format("{}{}/{} rows {} of {}\n", kMarker, r.shard, r.shards, r.points.size(), r.total_points);
}

void merge_sweep_csv(std::ostream& out, const std::vector<std::string>& paths) {
  if (paths.empty()) throw SizingInputError("sweep merge: give the part CSVs");
  struct Part {
    std::string path, header, rows;
    std::size_t rows_n = 0, total = 0;
  };
  std::map<std::size_t, Part> parts;
  std::size_t shards = 0;
  for (const std::string& path : paths) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw SizingInputError(fmt::format("sweep merge: {}: cannot read the file", path));
    std::string marker;
    std::getline(in, marker);
    unsigned long long i = 0, n = 0, rows = 0, total = 0;
    char tail = 0;
    if (marker.rfind(kMarker, 0) != 0 ||
        std::sscanf(marker.c_str() + std::char_traits<char>::length(kMarker), "%llu/%llu rows %llu of %llu%c", &i, &n,
                    &rows, &total, &tail) != 4) {
      throw SizingInputError(fmt::format("sweep merge: {}:1: not a shard of `sweep --shard` (no '{}i/N ...' line)", path,
                                         kMarker));
    }
    if (shards == 0) shards = n;
    if (n != shards) throw SizingInputError(fmt::format("sweep merge: {}: shard {}/{} but another part has N = {}", path, i, n, shards));
    Part p;
    p.path = path;
    std::getline(in, p.header);
    std::ostringstream body;
    body << in.rdbuf();
    p.rows = body.str();
    p.rows_n = static_cast<std::size_t>(std::count(p.rows.begin(), p.rows.end(), '\n'));
    p.total = total;
    if (p.rows_n != rows) {
      throw SizingInputError(fmt::format("sweep merge: {}: {} rows, the shard line says {} (truncated?)", path, p.rows_n, rows));
    }
    if (!parts.emplace(i, std::move(p)).second) throw SizingInputError(fmt::format("sweep merge: {}: shard {}/{} given twice", path, i, n));
  }
  for (std::size_t i = 1; i <= shards; ++i) {
    if (!parts.count(i)) throw SizingInputError(fmt::format("sweep merge: shard {}/{} is missing", i, shards));
  }
  const Part& first = parts.begin()->second;
  std::size_t sum = 0;
  for (const auto& [i, p] : parts) {
    if (p.header != first.header || p.total != first.total) {
      throw SizingInputError(fmt::format("sweep merge: {} is from another sweep than {}", p.path, first.path));
    }
    if (p.rows_n != io::shard_range(i, shards, p.total).second - io::shard_range(i, shards, p.total).first) {
      throw SizingInputError(fmt::format("sweep merge: {}: wrong number of rows for shard {}/{}", p.path, i, shards));
    }
    sum += p.rows_n;
  }
  if (sum != first.total) throw SizingInputError(fmt::format("sweep merge: {} rows, the sweep has {}", sum, first.total));
  out << first.header << '\n';
  for (const auto& [i, p] : parts) out << p.rows;
}

} // namespace sreh::sizing
