// The twin as a value (issue 13, A-TWIN-34..36): snapshot a running twin,
// try something else, restore, and it continues bit for bit as it did the
// first time: trace rows, move records, MuJoCo state, thermal nodes.
#include <gtest/gtest.h>

#include <cstring>
#include <stdexcept>
#include <vector>

#include "device_logic/units.hpp"
#include "twin/plant.hpp"
#include "twin/twin.hpp"
#include "twin/twin_snapshot.hpp"

namespace sreh {
namespace {

// Everything observable after a cycle, as raw bits (doubles bit for bit).
struct Bits {
  std::vector<uint64_t> v;
  void put(double x) {
    uint64_t b = 0;
    std::memcpy(&b, &x, sizeof b);
    v.push_back(b);
  }
  void put(uint64_t x) { v.push_back(x); }
  void row(const TraceRow& r) {
    put(uint64_t{static_cast<uint8_t>(r.state)}), put(r.setpoint_deg), put(r.position_deg), put(r.tracking_error_deg);
    put(r.velocity_dps), put(r.torque_Nm), put(r.torque_limit_Nm), put(r.supply_V), put(r.temperature_C);
    put(uint64_t{r.error_code}), put(uint64_t{r.warning_code}), put(uint64_t{static_cast<uint8_t>(r.led)});
    put(uint64_t{r.moving}), put(uint64_t{r.settling}), put(uint64_t{r.moves_started}), put(r.tolerance_deg);
    put(r.t_s), put(r.external_torque_Nm), put(uint64_t{static_cast<uint8_t>(r.iolink_led)});
    for (uint8_t b : r.pd_out) put(uint64_t{b});
    for (uint8_t b : r.pd_in) put(uint64_t{b});
  }
  // The plant beyond the trace: MuJoCo's state and the slow thermal nodes.
  void plant(const Plant& p) {
    put(p.rotor_angle_rad()), put(p.twist_rad()), put(p.rotor_velocity_rad_s()), put(p.velocity_rad_s());
    put(p.thermal().winding_C()), put(p.thermal().housing_C()), put(p.supply().bus_voltage_V());
    put(p.motor_current_A()), put(p.ghost_angle_rad()), put(p.steps());
  }
};

void set(Twin& t, bool motor_on, double target_deg, bool move) {
  ProcessDataOut pd;
  pd.motor_on = motor_on;
  pd.target_raw = static_cast<int32_t>(deg_to_wire_counts(target_deg));
  pd.parameter_set = 1;
  pd.move = move;
  t.set_pd_out(pd);
}

// The same n cycles with a second move half way; every row and plant state.
Bits continue_for(Twin& t, int n) {
  Bits bits;
  for (int i = 0; i < n; ++i) {
    if (i == n / 2) set(t, true, 90.0, false);
    if (i == n / 2 + 5) set(t, true, -60.0, true);
    t.run_cycle();
    bits.row(t.last_row());
    bits.plant(t.plant());
  }
  for (const MoveRecord& m : t.moves()) bits.put(m.end_deg), bits.put(uint64_t{static_cast<uint8_t>(m.outcome)});
  bits.put(t.max_tracking_error_deg()), bits.put(t.cycles()), bits.put(t.time_s());
  return bits;
}

TwinConfig loaded() {
  TwinConfig c;
  c.load = DiskLoad{0.3, 0.08, 0.01}; // 9600 g cm^2
  return c;
}

// Parameter set 1 configured for the mounted 9600 g cm^2 (index 65.4,
// manual 6.2); motor on, a move to 90 deg, stopped mid-move.
void start_mid_move(Twin& t) {
  const uint8_t load[2] = {9600 >> 8, 9600 & 0xFF};
  ASSERT_TRUE(t.isdu_write(65, 4, load).ok());
  set(t, true, 0.0, false);
  for (int i = 0; i < 30; ++i) t.run_cycle();
  ASSERT_TRUE(t.pd_in().ready);
  set(t, true, 90.0, true);
  for (int i = 0; i < 40; ++i) t.run_cycle();
  ASSERT_TRUE(t.telemetry().moving) << "state " << static_cast<int>(t.telemetry().state) << " error "
                                    << int{t.telemetry().error_code}; // mid-move
}

// Something else entirely, after the snapshot: world, master, device, load.
void try_something_else(Twin& t) {
  t.set_external_torque(0.3);
  t.set_supply_voltage(19.0);
  t.set_ambient_C(60.0);
  for (int i = 0; i < 50; ++i) t.run_cycle();
  t.set_flange_blocked(true);
  t.set_load(InertiaLoad{3000});
  t.set_master_cycle_s(0.004);
  const uint8_t counterclockwise[1] = {1};
  (void)t.isdu_write(82, 0, counterclockwise); // positive direction (manual 4.2)
  set(t, false, 0.0, false);
  t.set_link_up(false);
  for (int i = 0; i < 50; ++i) t.run_cycle();
  t.power_cycle();
}

constexpr int kCycles = 400; // 0.8 s: the rest of the move, settling, a second move

TEST(TwinSnapshot, MidMoveRestoreContinuesBitIdentical_Issue13) {
  Twin twin(loaded());
  start_mid_move(twin);
  const TwinSnapshot snap = twin.snapshot();
  const std::vector<TraceRow> before = twin.trace();
  const Bits reference = continue_for(twin, kCycles);

  try_something_else(twin);
  twin.restore(snap);
  // A-TWIN-36: the kept trace is cut back to the snapshot.
  ASSERT_EQ(twin.trace().size(), before.size());
  EXPECT_EQ(twin.cycles(), 70u);
  EXPECT_FALSE(twin.flange_blocked());
  EXPECT_DOUBLE_EQ(twin.load_inertia_gcm2(), 9600.0);
  EXPECT_EQ(twin.master_cycle_s(), 0.002);
  EXPECT_TRUE(twin.device().snapshot() == snap.device);
  const Bits again = continue_for(twin, kCycles);
  EXPECT_EQ(again.v.size(), reference.v.size());
  EXPECT_TRUE(again.v == reference.v) << "the continuation after restore differs";
  // The kept trace is the one run: the rows before the snapshot unchanged.
  Bits kept_then, kept_now;
  for (const TraceRow& r : before) kept_then.row(r);
  for (std::size_t i = 0; i < before.size(); ++i) kept_now.row(twin.trace()[i]);
  EXPECT_TRUE(kept_then.v == kept_now.v);
  EXPECT_EQ(twin.trace().size(), before.size() + kCycles);
}

TEST(TwinSnapshot, RestoresIntoAnotherTwinOfTheSameConfig) {
  Twin a(loaded());
  start_mid_move(a);
  const TwinSnapshot snap = a.snapshot();
  const Bits reference = continue_for(a, kCycles);

  Twin b(loaded());
  b.restore(snap);
  EXPECT_TRUE(b.trace().empty()); // rows are not in the snapshot (A-TWIN-36)
  EXPECT_TRUE(continue_for(b, kCycles).v == reference.v);
}

TEST(TwinSnapshot, RestoresBlockedFlangeAndTrackingError) {
  Twin twin(loaded());
  start_mid_move(twin);
  twin.set_flange_blocked(true);
  for (int i = 0; i < 200 && twin.pd_in().error_code == 0; ++i) twin.run_cycle();
  ASSERT_NE(twin.pd_in().error_code, 0); // manual 2.4: the blocked flange gave an error
  const TwinSnapshot snap = twin.snapshot();
  const Bits reference = continue_for(twin, kCycles);

  twin.set_flange_blocked(false); // released, error acknowledged, moved on
  set(twin, false, 0.0, false);
  for (int i = 0; i < 100; ++i) twin.run_cycle();
  twin.restore(snap);
  EXPECT_TRUE(twin.flange_blocked()); // eq_active lives in mjModel (MuJoCo 2.2.2)
  EXPECT_NE(twin.pd_in().error_code, 0);
  EXPECT_TRUE(continue_for(twin, kCycles).v == reference.v);
}

TEST(TwinSnapshot, RestoresTheLoadAcrossALoadChange_A_TWIN_34) {
  Twin twin(loaded());
  start_mid_move(twin);
  twin.set_load(InertiaLoad{4000}); // a part released mid-move
  const TwinSnapshot light = twin.snapshot();
  const Bits reference = continue_for(twin, kCycles);

  twin.set_load(DiskLoad{0.3, 0.08, 0.01});
  for (int i = 0; i < 20; ++i) twin.run_cycle();
  twin.restore(light);
  EXPECT_NEAR(twin.load_inertia_gcm2(), 4000.0, 1e-6);
  EXPECT_TRUE(continue_for(twin, kCycles).v == reference.v);

  // Into a twin configured with the other load: the snapshot's load is mounted.
  Twin other(loaded());
  other.restore(light);
  EXPECT_NEAR(other.load_inertia_gcm2(), 4000.0, 1e-6);
  EXPECT_TRUE(continue_for(other, kCycles).v == reference.v);
}

TEST(TwinSnapshot, RefusesAnotherWorldAndChangesNothing_A_TWIN_35) {
  Twin a(loaded());
  start_mid_move(a);
  const TwinSnapshot snap = a.snapshot();

  TwinConfig with_stop = loaded();
  with_stop.hard_stops.push_back(HardStop{120.0});
  Twin b(with_stop);
  for (int i = 0; i < 10; ++i) b.run_cycle();
  const TwinSnapshot b_before = b.snapshot();
  try {
    b.restore(snap);
    FAIL() << "restore into a twin with other hard stops must throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("hard_stops"), std::string::npos) << e.what();
  }
  EXPECT_EQ(b.cycles(), 10u);
  EXPECT_TRUE(b.device().snapshot() == b_before.device);
  EXPECT_EQ(b.plant().steps(), b_before.plant.steps);

  TwinConfig finer = loaded();
  finer.physics_dt_s = 5e-5;
  Twin c(finer);
  EXPECT_THROW(c.restore(snap), std::invalid_argument);
}

} // namespace
} // namespace sreh
