// The Device as a value (issue 13): configuration + state + monitors.
// A device restored from a snapshot mid-scenario continues bit for bit as
// the original: same motor commands, process data, telemetry, move records.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "device_logic/device_snapshot.hpp"
#include "device_logic/faults.hpp"
#include "device_logic/parameter_ids.hpp"
#include "tests/device_logic/device_rig.hpp"

namespace sreh {
using sreh::test::card_drive;
namespace {

using test::Rig;

// Everything a consumer sees, as raw bits (doubles compared bit for bit).
struct Log {
  std::vector<uint64_t> v;
  void put(double x) {
    uint64_t b = 0;
    std::memcpy(&b, &x, sizeof b);
    v.push_back(b);
  }
  void put(int64_t x) { v.push_back(static_cast<uint64_t>(x)); }
  void put(const MoveRecord& m) {
    put(int64_t{m.number}), put(int64_t{m.parameter_set}), put(m.start_ns), put(m.start_deg), put(m.target_deg);
    put(m.end_deg), put(m.tolerance_deg), put(m.wait_ms), put(m.settling_timeout_ms);
    put(int64_t{m.settling_timeout_active}), put(int64_t{m.stopped}), put(m.travel_s);
    put(m.settling_s.value_or(-1.0)), put(m.positioning_s.value_or(-1.0)), put(m.in_window_s.value_or(-1.0));
    put(m.max_tracking_error_deg), put(m.overshoot_deg), put(int64_t{static_cast<int>(m.outcome)});
    put(int64_t{m.error_code});
  }
  void put(const Telemetry& t) {
    put(int64_t{static_cast<int>(t.state)}), put(t.setpoint_deg), put(t.position_deg), put(t.tracking_error_deg);
    put(t.velocity_dps), put(t.torque_Nm), put(t.torque_limit_Nm), put(t.supply_V), put(t.temperature_C);
    put(int64_t{t.error_code}), put(int64_t{t.warning_code}), put(int64_t{static_cast<int>(t.led)});
    put(int64_t{t.moving}), put(int64_t{t.settling}), put(int64_t{t.moves_started}), put(t.tolerance_deg);
  }
};

constexpr int kCycles = 900; // 1.8 s of 2 ms cycles
constexpr int64_t kTrackingLimitTight = 1; // 87.1 raw: 0.1 deg (A-PARAM-1)

// A scenario-like sequence keyed by cycle: moves with several parameter
// sets, settling, a Stop, the locator, an ISDU write mid-run, a tracking
// error, a supply dip (114.4), a settling timeout (114.8), resets.
void script(Rig& r, int c, int64_t tracking_limit_default) {
  const ParamId limit = param::kTrackingErrorMax;
  switch (c) {
    case 0: r.pd.motor_on = true; break;
    case 3: r.command(126); break; // locator on (manual 6.6)
    case 5: r.start_move(120.0, 1); break;
    case 180: r.pd.move = false; break;
    case 190: r.start_move(-45.0, 2); break; // tight window, 50 ms wait
    case 400: r.pd.move = false; break;
    case 405: r.start_move(170.0, 1); break;
    case 420: r.pd.stop = true; break; // T4 while travelling
    case 470: r.pd.stop = false, r.pd.move = false; break;
    case 475: r.write_u(limit.index, limit.subindex, kTrackingLimitTight); break;
    case 480: r.start_move(0.0, 3); break; // load not configured, 0.1 deg allowed: 114.5
    case 560: r.pd.move = false, r.pd.motor_on = false, r.pd.reset_error = true; break;
    case 565: r.pd.reset_error = false; break;
    case 570: r.pd.motor_on = true, r.write_u(limit.index, limit.subindex, tracking_limit_default); break;
    case 600: r.start_move(300.0, 1); break;
    case 605: r.supply_V = 15.0; break; // mid-move, below 85.1: 114.4 after the debounce
    case 700: r.supply_V = 24.0, r.pd.move = false, r.pd.motor_on = false, r.pd.reset_error = true; break;
    case 705: r.pd.reset_error = false; break;
    case 720: r.pd.motor_on = true; break;
    case 730: r.start_move(60.0, 4); break; // window 0, 5 ms timeout: 114.8
    default: break;
  }
}

void configure(Rig& r) {
  r.load_kgm2 = gcm2_to_kgm2(2000);
  r.friction_Nm = 0.03; // the flange coasts to rest within the run after a trip
  auto set = [&](ParamId id, int64_t raw) { ASSERT_TRUE(r.write_u(id.index, id.subindex, raw).ok()) << id.index; };
  set(param::MotionSet{1}.load, 2000);
  const param::MotionSet set2{2}, set3{3}, set4{4};
  set(set2.load, 2000);
  set(set2.tolerance, 73);         // 0.05 deg
  set(set2.waiting_time, 500);     // 50 ms
  set(set2.settling_timeout, 4000); // 400 ms
  set(set3.speed, 40000);          // 4000 deg/s, load left at 0
  set(set4.load, 2000);
  set(set4.tolerance, 0);
  set(set4.settling_timeout, 50);  // 5 ms
}

// Cycles [from, to) of the script; every motor command, process data
// frame, telemetry sample, tracking peak and move record into `log`.
void run(Rig& r, int from, int to, Log& log, std::vector<MoveRecord>* moves = nullptr) {
  const int64_t limit_default = parameter_row(param::kTrackingErrorMax).default_value;
  for (int c = from; c < to; ++c) {
    script(r, c, limit_default);
    const auto frame = r.dev.exchange(encode(r.pd), r.outputs_valid);
    if (frame) {
      r.in = decode_in(*frame);
      for (uint8_t b : *frame) log.put(int64_t{b});
    }
    for (int i = 0; i < test::kStepsPerCycle; ++i) {
      const MotorCommand cmd = r.step();
      log.put(cmd.torque_Nm), log.put(int64_t{cmd.enabled});
    }
    log.put(r.dev.telemetry());
    log.put(r.dev.take_peak_tracking_error_deg());
    for (const MoveRecord& m : r.dev.take_finished_moves()) {
      log.put(m);
      if (moves) moves->push_back(m);
    }
    if (const auto p = r.dev.pending_move()) log.put(*p);
  }
}

class SnapshotRestore : public ::testing::TestWithParam<int> {};

TEST_P(SnapshotRestore, RestoredDeviceContinuesBitIdentically) {
  const int at = GetParam();
  Rig a;
  configure(a);
  Log before;
  run(a, 0, at, before);
  const DeviceSnapshot snap = a.dev.snapshot();
  Rig plant_at_snapshot = a; // the plant stub's own state, for the second run

  Log original;
  run(a, at, kCycles, original);

  // A fresh device that has lived a different life, then restored.
  Rig b = plant_at_snapshot;
  b.dev = Device(card_drive());
  b.dev.power_off();
  EXPECT_FALSE(b.dev.snapshot() == snap);
  b.dev.restore(snap);
  EXPECT_TRUE(b.dev.snapshot() == snap);
  Log restored;
  run(b, at, kCycles, restored);

  ASSERT_EQ(original.v.size(), restored.v.size());
  EXPECT_TRUE(original.v == restored.v);
  EXPECT_TRUE(a.dev.snapshot() == b.dev.snapshot()); // and the end states agree

  // The same through the constructor.
  Rig c = plant_at_snapshot;
  c.dev = Device(snap);
  Log constructed;
  run(c, at, kCycles, constructed);
  EXPECT_TRUE(original.v == constructed.v);
}

// Before the first move, mid-travel, while settling, mid-braking (Stop),
// at the tracking error, in the voltage debounce, in the settling timeout.
INSTANTIATE_TEST_SUITE_P(Device, SnapshotRestore, ::testing::Values(2, 40, 250, 430, 482, 606, 732));

TEST(Snapshot, ScenarioCoversMovesSettlingAndFaults) {
  // The sequence above does what the restore test claims it exercises.
  Rig r;
  configure(r);
  Log log;
  std::vector<MoveRecord> moves;
  uint8_t errors_seen = 0;
  for (int c = 0; c < kCycles; ++c) {
    run(r, c, c + 1, log, &moves);
    errors_seen |= r.in.error_code;
  }
  r.pd.motor_on = false;
  run(r, kCycles, kCycles + 1, log, &moves); // hands out the last record
  ASSERT_EQ(moves.size(), 6u);
  EXPECT_EQ(moves[0].outcome, MoveOutcome::Done);
  EXPECT_EQ(moves[1].parameter_set, 2);
  EXPECT_EQ(moves[1].outcome, MoveOutcome::Done);
  EXPECT_GE(*moves[1].settling_s, 0.05); // at least the waiting time of set 2 (manual 3.5.7)
  EXPECT_TRUE(moves[2].stopped);
  EXPECT_EQ(moves[3].outcome, MoveOutcome::Error);
  EXPECT_EQ(moves[4].outcome, MoveOutcome::Error);
  EXPECT_EQ(moves[5].outcome, MoveOutcome::Error);
  auto bit = [](ErrorBit b) { return 1u << static_cast<int>(b); };
  EXPECT_TRUE(moves[3].error_code & bit(ErrorBit::TrackingError));
  EXPECT_TRUE(moves[4].error_code & bit(ErrorBit::MotorVoltage));
  EXPECT_TRUE(moves[5].error_code & bit(ErrorBit::Positioning));
  EXPECT_TRUE(errors_seen & bit(ErrorBit::TrackingError));
}

TEST(Snapshot, EqualityNoticesEveryPart) {
  Device d{card_drive()};
  d.tick(1e-4, {}); // the first step records the maximum temperature (98, 99)
  const DeviceSnapshot s0 = d.snapshot();
  EXPECT_TRUE(d.snapshot() == s0);
  d.tick(1e-4, {}); // time advances: state
  EXPECT_FALSE(d.snapshot() == s0);
  EXPECT_TRUE(d.snapshot().configuration == s0.configuration);

  Device e{card_drive()};
  e.tick(1e-4, {});
  const std::vector<uint8_t> inactive{0};
  ASSERT_TRUE(e.isdu_write(param::kTrackingErrorActive.index, param::kTrackingErrorActive.subindex, inactive).ok());
  EXPECT_FALSE(e.snapshot().configuration == s0.configuration); // configuration

  Device f{card_drive()};
  f.tick(1e-4, {});
  f.set_master_cycle_time(0.032); // the link watchdog: a monitor
  EXPECT_FALSE(f.snapshot().monitors == s0.monitors);
  EXPECT_TRUE(f.snapshot().state == s0.state);
}

TEST(Snapshot, TickTakesIntegerNanoseconds) {
  // tick(dt_s) converts once to ns, rounded: 0.1 ms is 100'000 ns exactly.
  Device a{card_drive()}, b{card_drive()};
  const SensorReadings s{1000, 24.0, 25.0};
  for (int i = 0; i < 1000; ++i) {
    a.tick(1e-4, s);
    b.tick_ns(100'000, s);
  }
  EXPECT_TRUE(a.snapshot() == b.snapshot());
  EXPECT_EQ(a.snapshot().state.time_ns, 100'000'000);
  Device c{card_drive()};
  c.tick(1e-4 + 4e-10, s); // rounds to the nearest ns
  EXPECT_EQ(c.snapshot().state.time_ns, 100'000);
  c.tick(-1.0, s);         // negative: no time passes
  EXPECT_EQ(c.snapshot().state.time_ns, 100'000);
}

} // namespace
} // namespace sreh
