#include "scenarios/limits.hpp"

#include <cmath>
#include <variant>

#include <fmt/format.h>

#include "scenarios/scenario.hpp"
#include "twin/firmware_transfer.hpp"

namespace sreh {
namespace {

struct Bounder {
  double cycle_s;

  // Whole IO-Link cycles, as the runner counts them (A-SCN-3).
  double cycles_s(double d) const { return std::ceil(d / cycle_s - 1e-9) * cycle_s; }

  RunBound of(const std::vector<Step>& steps) const {
    RunBound b;
    for (const Step& s : steps) add(b, one(s));
    return b;
  }

  static void add(RunBound& b, const RunBound& x) {
    b.sim_s += x.sim_s;
    b.steps += x.steps;
    b.checks += x.checks;
  }

  RunBound one(const Step& step) const {
    RunBound b{0, 1, 0};
    std::visit(
        [&](const auto& a) {
          using T = std::decay_t<decltype(a)>;
          if constexpr (std::is_same_v<T, PdStep>) b.sim_s = cycle_s;
          else if constexpr (std::is_same_v<T, WaitStep>) b.sim_s = cycles_s(a.duration_s);
          else if constexpr (std::is_same_v<T, WaitUntilStep>) { b.sim_s = cycles_s(a.within_s); b.checks = 1; }
          else if constexpr (std::is_same_v<T, ExpectStep> || std::is_same_v<T, IsduReadStep> ||
                             std::is_same_v<T, IsduWriteStep>) b.checks = 1;
          else if constexpr (std::is_same_v<T, TorqueStep>) b.sim_s = a.for_s ? cycles_s(*a.for_s) : 0.0;
          else if constexpr (std::is_same_v<T, LinkStep>) {
            // down for down_s, then one cycle for the master's first exchange; `link: down` alone takes none
            b.sim_s = a.mode == LinkStep::Mode::Down ? 0.0 : cycles_s(a.down_s) + cycle_s;
          } else if constexpr (std::is_same_v<T, PowerCycleStep>) b.sim_s = cycles_s(a.off_s);
          else if constexpr (std::is_same_v<T, ReplaceDeviceStep>) { b.sim_s = 8 * cycle_s; b.checks = a.restore ? 1 : 0; } // start-up, then the download
          else if constexpr (std::is_same_v<T, FirmwareStep>) {
            // The transfer over ISDU takes cycles per chunk (twin/firmware_transfer.hpp).
            const std::vector<uint8_t> image = Device::firmware_image(a.version, a.size_B);
            double cycles = 0;
            for (const IsduWriteRequest& w : firmware_requests(image)) {
              cycles += static_cast<double>(isdu_write_cycles(w.data.size()));
            }
            b.sim_s = cycles * cycle_s;
            b.checks = 1;
          }
          else if constexpr (std::is_same_v<T, RepeatStep>) {
            const RunBound inner = of(a.steps);
            const double n = static_cast<double>(a.times);
            b = RunBound{n * inner.sim_s, 1 + n * inner.steps, n * inner.checks};
          }
        },
        step.action);
    return b;
  }
};

} // namespace

RunBound run_bound(const Scenario& s) {
  RunBound b = Bounder{s.sim.cycle_s}.of(s.steps);
  b.checks += static_cast<double>(s.device.isdu.size() + s.expect.size());
  return b;
}

void check_run_bound(const Scenario& s, const Limits& limits) {
  const Bounder bounder{s.sim.cycle_s};
  RunBound total{0, 0, static_cast<double>(s.device.isdu.size() + s.expect.size())};
  for (const Step& step : s.steps) {
    Bounder::add(total, bounder.one(step));
    const char* what = nullptr;
    std::string detail;
    if (total.sim_s > limits.max_sim_s + 1e-9) {
      what = "--max-sim-s";
      detail = fmt::format("up to {:g} s simulated by here (repeat counts x durations), above the limit of {:g} s",
                           total.sim_s, limits.max_sim_s);
    } else if (total.steps > static_cast<double>(limits.max_steps)) {
      what = "--max-steps";
      detail = fmt::format("up to {:g} steps executed by here (repeats unrolled), above the limit of {}", total.steps,
                           limits.max_steps);
    } else if (total.checks > static_cast<double>(limits.max_checks)) {
      what = "--max-checks";
      detail = fmt::format("up to {:g} checks recorded by here (repeats unrolled), above the limit of {}",
                           total.checks, limits.max_checks);
    }
    if (what) throw ScenarioError(step.loc, fmt::format("step {}: {}; refused before running (raise it with {})",
                                                       step.number, detail, what));
  }
}

} // namespace sreh
