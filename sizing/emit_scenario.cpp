// --emit-scenario (issue 17 hand-over): the sized cycle as a scenario the
// twin runs (`sreh-twin run FILE`), so that a machine builder can replay,
// inspect and keep it as a regression test.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <variant>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "device_logic/planner.hpp"
#include "device_logic/units.hpp"
#include "io/atomic_file.hpp"
#include "sizing/cycle_output.hpp"
#include "sizing/run_parts.hpp"

namespace sreh::sizing {
namespace {

std::string num(double v) { return fmt::format("{}", v); }

// A LoadSpec in the scenario's `load:` syntax (flow style).
std::string load_yaml(const LoadSpec& load) {
  struct V {
    std::string operator()(const NoLoad&) const { return "{none: true}"; }
    std::string operator()(const DiskLoad& d) const {
      return fmt::format("{{disk: {{mass_kg: {}, radius_m: {}, thickness_m: {}}}}}", num(d.mass_kg), num(d.radius_m),
                         num(d.thickness_m));
    }
    std::string operator()(const RingLoad& r) const {
      return fmt::format("{{ring: {{mass_kg: {}, inner_radius_m: {}, outer_radius_m: {}, thickness_m: {}}}}}",
                         num(r.mass_kg), num(r.inner_radius_m), num(r.outer_radius_m), num(r.thickness_m));
    }
    std::string operator()(const BoxLoad& b) const {
      return fmt::format("{{box: {{mass_kg: {}, x_m: {}, y_m: {}, z_m: {}}}}}", num(b.mass_kg), num(b.x_m), num(b.y_m),
                         num(b.z_m));
    }
    std::string operator()(const ArmLoad& a) const {
      return fmt::format("{{arm: {{mass_kg: {}, radius_m: {}, arm_mass_kg: {}}}}}", num(a.mass_kg), num(a.radius_m),
                         num(a.arm_mass_kg));
    }
    std::string operator()(const InertiaLoad& j) const { return fmt::format("{{inertia_gcm2: {}}}", num(j.inertia_gcm2)); }
    std::string operator()(const MjcfLoad& m) const {
      // Absolute, so that the scenario works wherever it is written; a JSON
      // string is a valid YAML double-quoted scalar.
      return fmt::format("{{mjcf: {}}}", nlohmann::json(std::filesystem::absolute(m.path).string()).dump());
    }
    std::string operator()(const CylinderPart& c) const {
      return fmt::format("{{cylinder: {{mass_kg: {}, radius_m: {}, length_m: {}}}}}", num(c.mass_kg), num(c.radius_m),
                         num(c.length_m));
    }
    std::string operator()(const SpherePart& c) const {
      return fmt::format("{{sphere: {{mass_kg: {}, radius_m: {}}}}}", num(c.mass_kg), num(c.radius_m));
    }
    std::string operator()(const PointPart& c) const { return fmt::format("{{point: {{mass_kg: {}}}}}", num(c.mass_kg)); }
    std::string operator()(const MeshPart& m) const {
      const std::string amount = m.mass_kg > 0 ? "mass_kg: " + num(m.mass_kg) : "density_kg_m3: " + num(m.density_kg_m3);
      return fmt::format("{{mesh: {{file: {}, {}, scale: {}}}}}",
                         nlohmann::json(std::filesystem::absolute(m.path).string()).dump(), amount, num(m.scale));
    }
    std::string operator()(const AssemblyLoad& a) const {
      std::string parts;
      for (const LoadPart& p : a.parts) {
        const std::string shape = std::visit(*this, p.shape); // "{kind: {...}}"
        parts += fmt::format("{}{{{}, at_m: [{}, {}, {}], rpy_deg: [{}, {}, {}]}}", parts.empty() ? "" : ", ",
                             shape.substr(1, shape.size() - 2), num(p.at_m[0]), num(p.at_m[1]), num(p.at_m[2]),
                             num(p.rpy_deg[0]), num(p.rpy_deg[1]), num(p.rpy_deg[2]));
      }
      return "{parts: [" + parts + "]}";
    }
  };
  return std::visit(V{}, load);
}

// `model: FILE`, absolute (the scenario may be written anywhere); "" without one.
std::string model_yaml(const WorldSetup& world) {
  if (world.model_file.empty()) return "";
  const std::string model = std::filesystem::absolute(world.model_file).lexically_normal().string();
  const char* whose = world.model_loc.line > 0 ? "the cycle file's model:" : "the sizing's --model";
  return fmt::format("model: {}  # {}\n", nlohmann::json(model).dump(), whose);
}

// `world: {hard_stops: [...]}`; "" without any.
std::string hard_stops_yaml(const std::vector<HardStop>& stops) {
  if (stops.empty()) return "";
  std::string list;
  for (const HardStop& h : stops) list += fmt::format("{}{{angle_deg: {}}}", list.empty() ? "" : ", ", num(h.angle_deg));
  return "world: {hard_stops: [" + list + "]}\n";
}

bool has_load_change(const CycleRequest& rq) {
  for (const CycleSegment& s : rq.segments) {
    if (std::holds_alternative<CycleLoadChange>(s.what)) return true;
  }
  return false;
}

} // namespace

CycleRequest cycle_of_single(const SizingRequest& rq) {
  CycleRequest c;
  c.file = "size";
  c.world = rq.world;
  c.settling = rq.settling;
  c.thermal_margin_K = rq.thermal_margin_K;
  c.handshake_cycles = rq.handshake_cycles;
  c.cycles = rq.cycles;
  CycleMove out, back;
  out.target_deg = rq.angle_deg;
  out.parameter_set = back.parameter_set = rq.parameter_set;
  back.target_deg = 0;
  for (int i = 0; i < 2; ++i) {
    CycleSegment move, dwell;
    move.what = i == 0 ? out : back;
    dwell.what = CycleDwell{rq.dwell_s, 0.0};
    c.segments.push_back(std::move(move));
    c.segments.push_back(std::move(dwell));
  }
  return c;
}

std::string scenario_yaml(const CycleRequest& rq, const std::vector<ParameterSetValues>& sets,
                          const std::vector<int>& set_of_segment, const std::string& name) {
  auto set_values = [&](int n) -> const ParameterSetValues& {
    for (const ParameterSetValues& s : sets) {
      if (s.set == n) return s;
    }
    throw std::logic_error(fmt::format("emit scenario: no values for parameter set {}", n));
  };
  std::string y;
  y += fmt::format("# Written by sreh-twin size --emit-scenario: the sized cycle replayed in the twin.\n"
                   "# Run it with: sreh-twin run THIS_FILE\n");
  y += fmt::format("name: {}\n", nlohmann::json(name).dump());
  y += model_yaml(rq.world);
  y += "device:\n";
  y += fmt::format("  supply_V: {}\n  ambient_C: {}\n", num(rq.world.supply.voltage_V), num(rq.world.thermal.ambient_C));
  if (rq.world.supply.source_resistance_ohm > 0) y += fmt::format("  source_resistance_ohm: {}\n", num(rq.world.supply.source_resistance_ohm));
  if (rq.world.supply.bus_capacitance_F > 0) y += fmt::format("  bus_capacitance_F: {}\n", num(rq.world.supply.bus_capacitance_F));
  y += "  isdu:  # every parameter set the cycle uses (manual 6.2, index 64 + n)\n";
  std::vector<std::pair<uint16_t, uint8_t>> written;
  for (const ParameterSetValues& s : sets) {
    for (const IsduWrite& w : s.writes) {
      if (std::find(written.begin(), written.end(), std::pair{w.index, w.subindex}) != written.end()) continue;
      written.emplace_back(w.index, w.subindex);
      y += fmt::format("    - {{index: {}, subindex: {}, value: {}}}  # {}\n", w.index, w.subindex, w.value, w.comment);
    }
  }
  y += fmt::format("load: {}\n", load_yaml(rq.world.load));
  y += fmt::format("mounting: {{tilt_deg: {}}}\n", num(rq.world.mounting_tilt_deg));
  y += hard_stops_yaml(rq.world.hard_stops);
  y += "steps:\n";
  y += "  - pd: {motor_on: 1}\n";
  y += "  - wait_until: {state: Ready, within_s: 0.1}\n";
  const std::string in = "  ";
  int64_t last_target = 0; // wire counts, as the device keeps its target
  int moves = 0;
  std::optional<double> torque_now; // the external torque in force (A-SIZE-21)
  auto set_torque = [&](double t, const std::string& why) {
    if (torque_now && t == *torque_now) return;
    y += in + fmt::format("- torque: {{Nm: {}}}  # {}\n", num(t), why);
    torque_now = t;
  };
  // Unrolled, not `repeat:`: relative moves end at a different absolute
  // position in every repetition, and each move's position is checked.
  for (int rep = 0; rep < rq.cycles; ++rep) {
    y += in + fmt::format("- comment: repetition {} of {}\n", rep + 1, rq.cycles);
    if (rep > 0 && has_load_change(rq)) {
      y += in + fmt::format("- load: {}  # every repetition starts with the cycle's load\n", load_yaml(rq.world.load));
    }
    for (std::size_t i = 0; i < rq.segments.size(); ++i) {
      const CycleSegment& seg = rq.segments[i];
      if (const auto* m = std::get_if<CycleMove>(&seg.what)) {
        ++moves;
        const ParameterSetValues& s = set_values(set_of_segment[i]);
        const int64_t wire = deg_to_wire_counts(m->target_deg);
        const int64_t end = m->relative ? last_target + wire : wire;
        const int64_t distance = end - last_target;
        const MotionLimits lim =
            limits_from_parameter_set(s.setting.speed_dps, s.setting.accel_pct, s.setting.jerk_pct, s.load_gcm2);
        const double travel_s = distance == 0 ? 0.0
            : Profile::rest_to_rest(internal_counts_to_rad(distance * kInternalPerWireCount), lim).duration_s();
        const double torque = m->process_torque_Nm.value_or(rq.process_torque_Nm);
        // Done in time: travel + settling timeout + the slack sizing allows (A-SIZE-3).
        const double within_s = std::ceil((travel_s + s.timeout_ms * 1e-3 + kMoveSlack_s) * 1000.0) / 1000.0;
        const double target = wire_counts_to_deg(end);
        const double window = s.tolerance_deg + 360.0 / 65536.0; // the window plus one wire count (manual 2.5)
        set_torque(distance > 0 ? -torque : distance < 0 ? torque : 0.0, "process torque against the motion");
        y += in + fmt::format("- pd: {{target_deg: {}, relative: {}, parameter_set: {}, move: 1}}  # segment {} (line {})\n",
                              num(m->relative ? wire_counts_to_deg(wire) : target), m->relative ? 1 : 0, s.set, i + 1,
                              seg.line);
        y += in + fmt::format("- wait_until: {{state: Done, within_s: {}}}\n", num(within_s));
        y += in + fmt::format("- expect: {{error: false, position_deg: [{}, {}]}}\n", num(target - window),
                              num(target + window));
        y += in + "- pd: {move: 0}  # manual 3.2 T7\n";
        last_target = end;
      } else if (const auto* d = std::get_if<CycleDwell>(&seg.what)) {
        set_torque(d->process_torque_Nm, "holding torque during the dwell");
        if (d->dwell_s > 0) y += in + fmt::format("- wait_s: {}  # dwell (segment {})\n", num(d->dwell_s), i + 1);
        y += in + "- expect: {error: false}\n";
      } else {
        y += in + fmt::format("- load: {}  # grip / release (segment {})\n",
                              load_yaml(std::get<CycleLoadChange>(seg.what).load), i + 1);
      }
    }
  }
  y += "expect:\n";
  y += fmt::format("  moves: {}\n  moves_completed: {}\n", moves, moves);
  return y;
}

void write_scenario_file(const std::string& path, const std::string& yaml) {
  io::write_file_atomic(path, [&](std::ostream& out) { out << yaml; });
}

} // namespace sreh::sizing
