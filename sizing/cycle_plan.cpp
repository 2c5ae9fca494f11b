// plan_sets (A-SIZE-18): which parameter set every move of a cycle uses,
// with the load it carries and the values given in the file.
#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include <fmt/format.h>

#include "device_logic/units.hpp"
#include "sizing/cycle.hpp"
#include "twin/load_builder.hpp"

namespace sreh::sizing {
namespace {

// Manual 2.5: process-data positions are int32 wire counts, +-2^15 revolutions.
constexpr double kWirePositionLimit_deg = 32768.0 * 360.0;

std::string where(const CycleRequest& rq, const CycleSegment& s) {
  return fmt::format("{}:{}:{}", rq.file, s.line, s.column);
}

// The load's inertia about the axis as MuJoCo computes it (A-SIZE-13).
double inertia_gcm2(const LoadSpec& load, const std::string& where) {
  try {
    const BuiltModel built = build_model(load, {}, 1e-4);
    const double j = std::max(0.0, kgm2_to_gcm2(built.load_inertia_kgm2));
    if (j > max_load_gcm2() + 1e-6) {
      throw SizingInputError(fmt::format("{}: load inertia {:.1f} g cm^2 is above the module's limit of {} g cm^2 "
                                         "(manual 3.5.6, 6.2 index 64.4)", where, j, max_load_gcm2()));
    }
    return j;
  } catch (const std::invalid_argument& e) {
    throw SizingInputError(fmt::format("{}: {}", where, e.what()));
  }
}

std::optional<MotionSetting> given_setting(const CycleMove& m) {
  if (!m.speed_dps && !m.accel_pct && !m.jerk_pct) return std::nullopt;
  const MotionSetting factory; // values left out keep the factory value of sets 1..7 (manual 6.2)
  return MotionSetting{m.speed_dps.value_or(factory.speed_dps), m.accel_pct.value_or(factory.accel_pct),
                       m.jerk_pct.value_or(factory.jerk_pct)};
}

bool same(const std::optional<MotionSetting>& a, const std::optional<MotionSetting>& b) {
  if (a.has_value() != b.has_value()) return false;
  return !a || (a->speed_dps == b->speed_dps && a->accel_pct == b->accel_pct && a->jerk_pct == b->jerk_pct);
}

// The load of every segment: the file's load at the start of each
// repetition (A-SIZE-19), changed by load segments.
void segment_loads(const CycleRequest& rq, std::vector<double>& seg_load, std::vector<const LoadSpec*>& seg_spec) {
  const std::string top = fmt::format("{}:{}:{}: load", rq.file, rq.world.load_loc.line, rq.world.load_loc.column);
  double now = inertia_gcm2(rq.world.load, top);
  const LoadSpec* spec = &rq.world.load;
  seg_load.assign(rq.segments.size(), now);
  seg_spec.assign(rq.segments.size(), spec);
  for (std::size_t i = 0; i < rq.segments.size(); ++i) {
    if (const auto* l = std::get_if<CycleLoadChange>(&rq.segments[i].what)) {
      now = inertia_gcm2(l->load, where(rq, rq.segments[i]));
      spec = &l->load;
    }
    seg_load[i] = now;
    seg_spec[i] = spec;
  }
}

// The longest distance of each move over the repetitions (the first
// starts at 0); relative moves must stay inside the position range.
std::vector<double> longest_distances(const CycleRequest& rq) {
  std::vector<double> distance(rq.segments.size(), 0.0);
  double pos = 0;
  for (int rep = 0; rep < std::max(2, rq.cycles); ++rep) {
    for (std::size_t i = 0; i < rq.segments.size(); ++i) {
      const auto* m = std::get_if<CycleMove>(&rq.segments[i].what);
      if (!m) continue;
      const double to = m->relative ? pos + m->target_deg : m->target_deg;
      distance[i] = std::max(distance[i], std::abs(to - pos));
      pos = to;
      if (std::abs(pos) >= kWirePositionLimit_deg) {
        throw SizingInputError(fmt::format("{}: repetition {} reaches {} deg, outside the position range of "
                                           "+-32768 revolutions (manual 2.5)", where(rq, rq.segments[i]), rep + 1, pos));
      }
    }
  }
  return distance;
}

// An assigned set: the lowest free of 1..7, then 0 (the factory sets are
// equal, manual 6.2); -1 when all eight are taken.
int lowest_free_set(const std::vector<SetPlan>& sets) {
  for (int n : {1, 2, 3, 4, 5, 6, 7, 0}) {
    if (std::none_of(sets.begin(), sets.end(), [&](const SetPlan& q) { return q.set == n; })) return n;
  }
  return -1;
}

} // namespace

CyclePlan plan_sets(const CycleRequest& rq) {
  std::vector<double> seg_load;
  std::vector<const LoadSpec*> seg_spec;
  segment_loads(rq, seg_load, seg_spec);
  const std::vector<double> distance = longest_distances(rq);

  CyclePlan plan;
  plan.move_set.assign(rq.segments.size(), -1);
  std::map<int, std::size_t> by_number;       // explicit set numbers
  std::vector<std::size_t> first_use;          // segment that created each plan entry
  auto load_raw = [](double gcm2) { return std::lround(gcm2); }; // 64+n.4 counts 1 g cm^2
  // Explicit set numbers first, so that assigned numbers avoid them.
  for (int pass = 0; pass < 2; ++pass) {
    for (std::size_t i = 0; i < rq.segments.size(); ++i) {
      const auto* m = std::get_if<CycleMove>(&rq.segments[i].what);
      if (!m || m->parameter_set.has_value() != (pass == 0)) continue;
      const std::optional<MotionSetting> given = given_setting(*m);
      std::optional<std::size_t> found;
      if (m->parameter_set) {
        if (auto it = by_number.find(*m->parameter_set); it != by_number.end()) found = it->second;
      } else {
        for (std::size_t k = 0; k < plan.sets.size(); ++k) {
          const SetPlan& p = plan.sets[k];
          if (load_raw(p.load_gcm2) == load_raw(seg_load[i]) && same(p.given, given) &&
              !std::any_of(by_number.begin(), by_number.end(), [&](const auto& e) { return e.second == k; })) {
            found = k;
          }
        }
      }
      if (found) {
        SetPlan& p = plan.sets[*found];
        const CycleSegment& first = rq.segments[first_use[*found]];
        if (load_raw(p.load_gcm2) != load_raw(seg_load[i])) {
          throw SizingInputError(fmt::format(
              "{}: parameter set {} is used with a load of {:.0f} g cm^2 here and {:.0f} g cm^2 at line {}; its "
              "configured load (64+n.4) can hold one: give each load its own set",
              where(rq, rq.segments[i]), p.set, seg_load[i], p.load_gcm2, first.line));
        }
        if (given && p.given && !same(given, p.given)) {
          throw SizingInputError(fmt::format("{}: parameter set {} is given other speed/accel/jerk values at line {}",
                                             where(rq, rq.segments[i]), p.set, first.line));
        }
        if (given) p.given = given;
        p.longest_move_deg = std::max(p.longest_move_deg, distance[i]);
        plan.move_set[i] = static_cast<int>(*found);
        continue;
      }
      SetPlan p;
      if (m->parameter_set) {
        p.set = *m->parameter_set;
      } else {
        p.set = lowest_free_set(plan.sets);
        if (p.set < 0) {
          throw SizingInputError(fmt::format("{}: the cycle needs more than the module's 8 parameter sets "
                                             "(index 64..71): different loads and given values each need one",
                                             where(rq, rq.segments[i])));
        }
      }
      p.load_gcm2 = seg_load[i];
      p.load = *seg_spec[i];
      p.given = given;
      p.longest_move_deg = distance[i];
      plan.sets.push_back(p);
      first_use.push_back(i);
      plan.move_set[i] = static_cast<int>(plan.sets.size() - 1);
      if (m->parameter_set) by_number[p.set] = plan.sets.size() - 1;
    }
  }
  return plan;
}

} // namespace sreh::sizing
