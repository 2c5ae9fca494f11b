// The gentlest search's proxy against the twin (issue 37, A-SIZE-26): for
// each single-move case, the sets the gentlest search would consider, in
// its order, run in the twin until their proxy is `--window` beyond the
// best feasible set's, one CSV row per run: the proxy (TorqueProxy), the
// previous proxy (the planned acceleration's RMS over the cycle, 48
// samples) and the simulated RMS torque. bench/gentle_proxy.py makes the
// cases and reads the rows (the spread of simulated / proxy within a case).
//
// usage: sizing_proxy_bench CASES.txt OUT.csv [--window W] [--threads N] [--max-runs N]
// CASES.txt: one case a line, `key=value` words: angle (deg), load (g cm^2)
// or loadfile (a load file), pos or cycle (the required positioning or
// cycle time, ms), dwell (s), V (supply), tilt (deg from vertical).
// With PROXY_TRACE="SPEED ACCEL JERK" in the environment: that set of the
// first case run once, its trace (time, set-point, position, speed,
// torque) written to OUT.csv (how the hold and cruise torques of
// docs/performance-sizing.md were seen).
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "device_logic/planner.hpp"
#include "device_logic/units.hpp"
#include "sizing/rms_proxy.hpp"
#include "sizing/size_options.hpp"
#include "sizing/sizing.hpp"

namespace sreh::sizing {
namespace {

SizeOptions parse_case(const std::string& line) {
  SizeOptions o;
  std::istringstream words(line);
  std::string w;
  while (words >> w) {
    const auto eq = w.find('=');
    if (eq == std::string::npos) throw std::invalid_argument("no key=value: " + w);
    const std::string key = w.substr(0, eq), value = w.substr(eq + 1);
    if (key == "loadfile") { o.load = value; continue; }
    const double v = std::stod(value);
    if (key == "angle") o.angle_deg = v;
    else if (key == "load") o.load_gcm2 = v;
    else if (key == "pos") o.max_positioning_ms = v;
    else if (key == "cycle") o.max_cycle_ms = v;
    else if (key == "dwell") o.dwell_s = v;
    else if (key == "V") o.voltage_V = v;
    else if (key == "tilt") o.mounting_tilt_deg = v;
    else throw std::invalid_argument("unknown key " + key);
  }
  return o;
}

// The proxy before issue 37's A-SIZE-26: RMS of the planned acceleration
// (48 midpoint samples of the move) over the cycle, inertia and friction left out.
double acceleration_proxy(const SizingRequest& rq, const MotionSetting& s, double load_gcm2, double hold_s) {
  const Profile p = Profile::rest_to_rest(internal_counts_to_rad(deg_to_wire_counts(rq.angle_deg) * kInternalPerWireCount),
                                          limits_from_parameter_set(s.speed_dps, s.accel_pct, s.jerk_pct, load_gcm2));
  constexpr int kSamples = 48;
  double sq = 0;
  for (int k = 0; k < kSamples; ++k) {
    const double a = p.at((k + 0.5) * p.duration_s() / kSamples).acc_rad_s2;
    sq += a * a;
  }
  return std::sqrt(sq / kSamples * p.duration_s() / (p.duration_s() + hold_s));
}

struct Row {
  std::size_t rank;
  PlannedSet set;
  double old_proxy;
  Evaluation ev;
};

std::vector<Row> measure(const std::string& line, double window, int max_runs) {
  const SizingRequest rq = make_request(parse_case(line));
  const double load = validate(rq);
  const std::vector<PlannedSet> order = gentlest_order(rq, load);
  const double hold_s = make_parameter_set(rq, MotionSetting{}, load).wait_ms * 1e-3 +
                        rq.handshake_cycles * TwinConfig{}.cycle_s + rq.dwell_s;
  std::vector<Row> rows;
  double best_proxy = -1;
  for (std::size_t i = 0; i < order.size() && static_cast<int>(rows.size()) < max_runs; ++i) {
    if (best_proxy > 0 && order[i].rms_proxy_Nm > best_proxy * (1 + window)) break;
    Row r{i, order[i], acceleration_proxy(rq, order[i].setting, load, hold_s),
          evaluate(rq, make_parameter_set(rq, order[i].setting, load), false)};
    if (r.ev.feasible && best_proxy < 0) best_proxy = order[i].rms_proxy_Nm;
    rows.push_back(std::move(r));
  }
  return rows;
}

int run(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: sizing_proxy_bench CASES.txt OUT.csv [--window W] [--threads N] [--max-runs N]\n";
    return 2;
  }
  double window = 0.08;
  int threads = 2, max_runs = 150;
  for (int i = 3; i + 1 < argc; i += 2) {
    const std::string k = argv[i];
    if (k == "--window") window = std::stod(argv[i + 1]);
    else if (k == "--threads") threads = std::stoi(argv[i + 1]);
    else if (k == "--max-runs") max_runs = std::stoi(argv[i + 1]);
    else { std::cerr << "unknown option " << k << "\n"; return 2; }
  }
  if (std::getenv("PROXY_TRACE")) {
    std::ifstream in1(argv[1]);
    std::string line;
    std::getline(in1, line);
    const SizingRequest rq = make_request(parse_case(line));
    const double load = validate(rq);
    std::istringstream w(std::getenv("PROXY_TRACE"));
    MotionSetting s;
    w >> s.speed_dps >> s.accel_pct >> s.jerk_pct;
    const Evaluation ev = evaluate(rq, make_parameter_set(rq, s, load), true);
    std::ofstream out(argv[2]);
    out << "t_s,setpoint_deg,position_deg,velocity_dps,torque_Nm\n";
    for (const TraceRow& r : ev.trace) out << r.t_s << ',' << r.setpoint_deg << ',' << r.position_deg << ',' << r.velocity_dps << ',' << r.torque_Nm << '\n';
    std::cout << "rms " << ev.rms_torque_Nm << " positioning " << ev.positioning_s << "\n";
    return 0;
  }
  std::vector<std::string> cases;
  std::ifstream in(argv[1]);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line[0] != '#') cases.push_back(line);
  }
  std::vector<std::vector<Row>> results(cases.size());
  std::vector<std::string> errors(cases.size());
  std::atomic<std::size_t> next{0};
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) {
    pool.emplace_back([&] {
      for (std::size_t c; (c = next++) < cases.size();) {
        try {
          results[c] = measure(cases[c], window, max_runs);
        } catch (const std::exception& e) {
          errors[c] = e.what();
        }
      }
    });
  }
  for (std::thread& t : pool) t.join();
  std::ofstream out(argv[2]);
  out << "case,rank,speed_dps,accel_pct,jerk_pct,travel_s,proxy_Nm,old_proxy,feasible,rms_torque_Nm,positioning_s,binding_limit\n";
  for (std::size_t c = 0; c < cases.size(); ++c) {
    if (!errors[c].empty()) std::cerr << "case " << c << " (" << cases[c] << "): " << errors[c] << "\n";
    for (const Row& r : results[c]) {
      char buf[512];
      std::snprintf(buf, sizeof buf, "%zu,%zu,%.1f,%g,%g,%.9g,%.9g,%.9g,%d,%.9g,%.9g,%s\n", c, r.rank,
                    r.set.setting.speed_dps, r.set.setting.accel_pct, r.set.setting.jerk_pct, r.set.travel_s,
                    r.set.rms_proxy_Nm, r.old_proxy, r.ev.feasible ? 1 : 0, r.ev.rms_torque_Nm, r.ev.positioning_s,
                    r.ev.binding_limit.c_str());
      out << buf;
    }
  }
  return 0;
}

} // namespace
} // namespace sreh::sizing

int main(int argc, char** argv) { return sreh::sizing::run(argc, argv); }
