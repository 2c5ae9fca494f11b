// Sizing over a grid (issue 8): loads x angles x voltages x settings, each
// point one size() (evaluate the given speed, or recommend), spread over
// std::threads, each with its own twins. The result order is the grid order
// whatever the thread count, and every point is deterministic, so the CSV is
// byte-identical for 1 or N threads.
#pragma once
#include <cstddef>
#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "sizing/sizing.hpp"
#include "sizing/uncertainty.hpp"

namespace sreh::sizing {

struct SweepRequest {
  std::vector<double> loads_gcm2;
  std::vector<double> angles_deg;
  std::vector<double> voltages_V = {24.0};
  std::vector<double> speeds_dps;     // empty: recommend a set per point
  double accel_pct = 100.0;           // with speeds_dps
  double jerk_pct = 100.0;
  SizingRequest base;                 // dwell, tolerance, wait, ambient, cycles, parameter set
  int threads = 2;
  // Shard `shard` of `shards` (1-based, issue 17): a contiguous block of the
  // grid, [floor((i-1) M / N), floor(i M / N)) of M points (A-SIZE-11).
  std::size_t shard = 1, shards = 1;
  // `sweep --uncertainty` (issue 26): each point also evaluated on `samples`
  // models drawn from `card`'s ranges (sizing/uncertainty.hpp).
  bool uncertainty = false;
  int samples = 32;
  uint64_t seed = 1;
  ModelCard card;
  // Called after each finished point (from worker threads, serialised).
  std::function<void(std::size_t done, std::size_t total)> progress;
};

struct SweepPoint {
  double load_gcm2 = 0;
  double angle_deg = 0;
  double voltage_V = 0;
  std::optional<double> speed_dps; // the given speed, or none (recommended)
  SizingResult result;
  std::optional<UncertaintyResult> uncertainty; // with SweepRequest::uncertainty
};

struct SweepResult {
  std::vector<SweepPoint> points; // loads outermost, then angles, voltages, speeds
  bool uncertainty = false;       // the points carry bands: the CSV has the _lo / _hi columns
  std::size_t shard = 1, shards = 1;
  std::size_t first_point = 0, total_points = 0; // the block of the whole grid these points are
};

// Which block a shard runs, and parsing --shard: io/shard.hpp (shared with `run DIR`).

// First line of a shard's CSV, before the header (only when sharded).
std::string shard_marker(const SweepResult& result);

// Joins shard CSVs (any order) into the unsharded CSV, byte for byte;
// throws SizingInputError for a missing, repeated or foreign part.
void merge_sweep_csv(std::ostream& out, const std::vector<std::string>& part_paths);

// The grid's requests in result order; throws SizingInputError for an
// empty axis or a value outside the module's limits (naming it).
std::vector<SizingRequest> sweep_requests(const SweepRequest& request);

SweepResult run_sweep(const SweepRequest& request);

// One header row, then one row per point in grid order.
void write_sweep_csv(std::ostream& out, const SweepResult& result);

// The inverse question: per angle, the heaviest load on the grid whose
// positioning time meets the target (feasible points only). Points are
// grouped by (voltage, speed); `group` selects one of them in order of
// first appearance.
struct HeaviestLoad {
  double angle_deg = 0;
  double target_s = 0;
  std::optional<double> load_gcm2; // none: no grid load meets it
};
struct SweepGroup {
  double voltage_V = 0;
  std::optional<double> speed_dps;
};
std::vector<SweepGroup> sweep_groups(const SweepResult& result);
std::vector<HeaviestLoad> heaviest_loads(const SweepResult& result, const SweepGroup& group,
                                         const std::vector<double>& targets_s);

} // namespace sreh::sizing
