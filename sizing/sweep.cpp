#include "sizing/sweep.hpp"

#include "io/shard.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <ostream>
#include <thread>

#include <fmt/format.h>

#include "sizing/sweep_options.hpp"

namespace sreh::sizing {
namespace {

constexpr std::size_t kMaxPoints = 100000; // A-SIZE-11

std::string csv_number(double v) { return fmt::format("{}", v); } // shortest round-trip text: deterministic

std::string csv_text(const std::string& s) {
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

bool same_group(const SweepPoint& p, const SweepGroup& g) {
  return p.voltage_V == g.voltage_V && p.speed_dps == g.speed_dps;
}

} // namespace

std::vector<SizingRequest> sweep_requests(const SweepRequest& rq) {
  if (rq.loads_gcm2.empty()) throw SizingInputError("--loads-gcm2: give at least one load");
  if (rq.angles_deg.empty()) throw SizingInputError("--angles-deg: give at least one angle");
  if (rq.voltages_V.empty()) throw SizingInputError("--voltages-V: give at least one voltage");
  const std::size_t settings = std::max<std::size_t>(1, rq.speeds_dps.size());
  const std::size_t n = rq.loads_gcm2.size() * rq.angles_deg.size() * rq.voltages_V.size() * settings;
  if (n > kMaxPoints) {
    throw SizingInputError(fmt::format("the sweep has {} points, more than {} (A-SIZE-11)", n, kMaxPoints));
  }
  std::vector<SizingRequest> out;
  out.reserve(n);
  for (double load : rq.loads_gcm2) {
    for (double angle : rq.angles_deg) {
      for (double voltage : rq.voltages_V) {
        for (std::size_t s = 0; s < settings; ++s) {
          SizingRequest r = rq.base;
          r.world.load = InertiaLoad{load};
          r.angle_deg = angle;
          r.world.supply.voltage_V = voltage;
          r.keep_trace = false;
          if (!rq.speeds_dps.empty()) r.setting = MotionSetting{rq.speeds_dps[s], rq.accel_pct, rq.jerk_pct};
          else r.setting.reset();
          out.push_back(std::move(r));
        }
      }
    }
  }
  return out;
}

SweepResult run_sweep(const SweepRequest& rq) {
  std::vector<SizingRequest> requests = sweep_requests(rq);
  for (const SizingRequest& r : requests) validate(r); // bad input before any long run, in every shard
  SweepResult result;
  result.shard = rq.shard;
  result.shards = rq.shards;
  result.total_points = requests.size();
  result.uncertainty = rq.uncertainty;
  if (rq.shards > 1) {
    const auto [begin, end] = io::shard_range(rq.shard, rq.shards, requests.size());
    result.first_point = begin;
    requests = std::vector<SizingRequest>(requests.begin() + static_cast<std::ptrdiff_t>(begin),
                                          requests.begin() + static_cast<std::ptrdiff_t>(end));
  }
  result.points.resize(requests.size());
  std::vector<std::exception_ptr> errors(requests.size());
  std::atomic<std::size_t> next{0};
  std::size_t done = 0;
  std::mutex progress_mutex;
  auto worker = [&] {
    for (std::size_t i = next++; i < requests.size(); i = next++) {
      SweepPoint& p = result.points[i];
      const SizingRequest& r = requests[i];
      p.load_gcm2 = std::get<InertiaLoad>(r.world.load).inertia_gcm2;
      p.angle_deg = r.angle_deg;
      p.voltage_V = r.world.supply.voltage_V;
      if (r.setting) p.speed_dps = r.setting->speed_dps;
      try {
        p.result = size(r);
        p.result.tried.clear(); // keep memory flat over large grids
        // One thread per point: the points already run in parallel.
        if (rq.uncertainty) p.uncertainty = size_uncertainty(r, rq.card, p.result.evaluation, rq.samples, rq.seed, 1);
      } catch (...) {
        errors[i] = std::current_exception();
      }
      if (rq.progress) {
        const std::lock_guard<std::mutex> lock(progress_mutex);
        rq.progress(++done, requests.size());
      }
    }
  };
  const int threads = std::clamp(rq.threads, 1, 64);
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  for (const std::exception_ptr& e : errors) {
    if (e) std::rethrow_exception(e); // the first failing point in grid order
  }
  return result;
}

void write_sweep_csv(std::ostream& out, const SweepResult& result) {
  const auto columns = sweep_columns(result.uncertainty);
  for (std::size_t c = 0; c < columns.size(); ++c) out << (c > 0 ? "," : "") << columns[c].name;
  out << '\n';
  for (const SweepPoint& p : result.points) {
    for (std::size_t c = 0; c < columns.size(); ++c) {
      if (c > 0) out << ',';
      const SweepCell cell = sweep_cell(p, c);
      if (const auto* v = std::get_if<double>(&cell)) out << csv_number(*v);
      else if (const auto* b = std::get_if<bool>(&cell)) out << (*b ? 1 : 0);
      else if (const auto* n = std::get_if<int64_t>(&cell)) out << *n;
      else if (const auto* t = std::get_if<std::string>(&cell)) out << (columns[c].kind == SweepColumnKind::Text ? csv_text(*t) : *t);
    }
    out << '\n';
  }
}

std::vector<SweepGroup> sweep_groups(const SweepResult& result) {
  std::vector<SweepGroup> groups;
  for (const SweepPoint& p : result.points) {
    if (std::none_of(groups.begin(), groups.end(), [&](const SweepGroup& g) { return same_group(p, g); })) {
      groups.push_back({p.voltage_V, p.speed_dps});
    }
  }
  return groups;
}

std::vector<HeaviestLoad> heaviest_loads(const SweepResult& result, const SweepGroup& group,
                                         const std::vector<double>& targets_s) {
  std::vector<double> angles;
  for (const SweepPoint& p : result.points) {
    if (std::find(angles.begin(), angles.end(), p.angle_deg) == angles.end()) angles.push_back(p.angle_deg);
  }
  std::vector<HeaviestLoad> out;
  for (double angle : angles) {
    for (double target : targets_s) {
      HeaviestLoad h{angle, target, std::nullopt};
      for (const SweepPoint& p : result.points) {
        const Evaluation& e = p.result.evaluation;
        if (p.angle_deg != angle || !same_group(p, group) || !e.feasible || e.positioning_s > target) continue;
        if (!h.load_gcm2 || p.load_gcm2 > *h.load_gcm2) h.load_gcm2 = p.load_gcm2;
      }
      out.push_back(h);
    }
  }
  return out;
}

} // namespace sreh::sizing
