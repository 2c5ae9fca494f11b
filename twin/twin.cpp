#include "twin/twin.hpp"

#include "device_logic/parameter_ids.hpp"

#include <cmath>
#include <stdexcept>

#include "device_logic/units.hpp"
#include "io/interrupt.hpp"
#include "twin/firmware_transfer.hpp"
#include "twin/plant.hpp"
#include "twin/twin_snapshot.hpp"

namespace sreh {
namespace {

// Manual 1: at least 2 ms; IO-Link's MasterCycleTime encoding ends at 132.8 ms (A-LINK-2).
constexpr double kMinCycle_s = 0.002;
constexpr double kMaxCycle_s = 0.1328;
constexpr int kStartupCycles = 2; // one STARTUP, one PREOPERATE cycle (A-LINK-3)

// Control periods per master cycle: the device runs on its own clock.
int periods_per_cycle(double cycle_s, double control_period_s) {
  if (!(control_period_s > 0) || !(cycle_s > 0)) {
    throw std::invalid_argument("twin: the control period and cycle_s must be positive");
  }
  if (cycle_s < kMinCycle_s - 1e-12 || cycle_s > kMaxCycle_s + 1e-12) {
    throw std::invalid_argument("twin: master cycle " + std::to_string(cycle_s) +
                                " s is outside 0.002 .. 0.1328 s (manual 1, IO-Link MasterCycleTime)");
  }
  const double ratio = cycle_s / control_period_s;
  const double rounded = std::round(ratio);
  if (rounded < 1 || std::abs(ratio - rounded) > 1e-9 * ratio) {
    throw std::invalid_argument("twin: cycle_s (" + std::to_string(cycle_s) +
                                ") must be an integer multiple of the drive's control period (" +
                                std::to_string(control_period_s) + " s)");
  }
  return static_cast<int>(rounded);
}

PlantConfig plant_config(const TwinConfig& c) {
  PlantConfig p;
  static_cast<WorldSpec&>(p) = c; // the world is one struct (twin/specs.hpp)
  p.visual_detail = c.visual_detail;
  return p;
}

// Checks the cycle before the plant is built (a bad config throws cheaply).
TwinRunState first_run_state(const TwinConfig& c) {
  TwinRunState r;
  r.steps = periods_per_cycle(c.cycle_s, c.module.drive.control_period_s());
  r.cycle_s = c.cycle_s;
  r.cycle_ns = seconds_to_ns(c.cycle_s);
  return r;
}

Device make_device(const TwinConfig& c) {
  // The firmware is built for the nominal motor, not the module's (A-CAL-11).
  const DriveModel drive = firmware_drive(c.module.drive, c.nominal_motor);
  return c.nvm_image ? Device(drive, *c.nvm_image) : Device(drive);
}

} // namespace

// The run's own state is a TwinRunState (twin/twin_snapshot.hpp): what a
// snapshot takes, field for field.
struct Twin::Impl : TwinRunState {
  explicit Impl(const TwinConfig& c)
      : TwinRunState(first_run_state(c)), config(c), plant(plant_config(c)), device(make_device(c)) {
    device.set_master_cycle_time(c.cycle_s); // announced before t = 0 (the run starts in OPERATE)
  }

  // Manual 4.2 (index 82): process-data degrees run against the physical
  // frame when the positive direction is counterclockwise. Only the ghost
  // marker needs this (the planned setpoint is in process-data degrees).
  void refresh_direction() {
    const IsduResult r = device.isdu_read(param::kPositiveDirection.index, param::kPositiveDirection.subindex);
    direction = (r.ok() && !r.data.empty() && r.data[0] == 1) ? -1.0 : 1.0;
  }

  // Move records come from the device (issue 13); the twin collects them on
  // the run's clock: the device counts from its own power-on.
  void collect_moves() {
    if (pending_in_list) {
      moves.pop_back();
      pending_in_list = false;
    }
    auto place = [&](MoveRecord m) {
      m.start_s = static_cast<double>(m.start_ns + device_epoch_ns) / 1e9;
      return m;
    };
    for (const MoveRecord& m : device.take_finished_moves()) {
      if (config.move_sink) config.move_sink(place(m)); // streamed (issue 12)
      else moves.push_back(place(m));
    }
    if (const auto m = device.pending_move()) {
      moves.push_back(place(*m));
      pending_in_list = true;
    }
  }

  void record_row(const PdOutFrame& out_frame) {
    TraceRow row;
    static_cast<Telemetry&>(row) = device.telemetry();
    row.t_s = static_cast<double>(time_ns) * 1e-9;
    row.torque_Nm = plant.applied_torque_Nm();
    row.external_torque_Nm = plant.external_torque_Nm();
    row.supply_V = plant.sensors().supply_V;
    row.temperature_C = plant.sensors().temperature_C;
    if (!device.powered()) row.led = LedColor::Off;
    row.pd_out = out_frame;
    row.pd_in = last_pd_in;
    row.iolink_led = device.io_link_led();
    last_row = row;
    if (config.trace_sink) config.trace_sink(row); // streamed: memory flat with run length (issue 12)
    else if (config.record_trace) trace.push_back(row);
  }

  void update_visuals() {
    const Telemetry tel = device.telemetry();
    plant.set_led_rgba(led_rgba(device.powered() ? tel.led : LedColor::Off));
    // Telemetry positions come from the encoder reading of the last tick.
    plant.set_ghost_angle(internal_counts_to_rad(ticked_counts) +
                          direction * deg_to_rad(tel.setpoint_deg - tel.position_deg));
  }

  TwinConfig config;
  Plant plant;
  Device device;
  std::vector<TraceRow> trace;
};

Twin::Twin(const TwinConfig& config) : impl_(std::make_unique<Impl>(config)) {
  // A run starts on a running rig: the master took the port through STARTUP
  // and PREOPERATE before t = 0 and has exchanged once (A-LINK-3).
  if (const auto in = impl_->device.exchange(encode(impl_->pd_out), impl_->outputs_valid)) impl_->last_pd_in = *in;
  impl_->refresh_direction();
  impl_->update_visuals();
}

Twin::~Twin() = default;

void Twin::set_pd_out(const ProcessDataOut& out) { impl_->pd_out = out; }
const ProcessDataOut& Twin::pd_out() const { return impl_->pd_out; }
void Twin::set_outputs_valid(bool valid) { impl_->outputs_valid = valid; }
void Twin::set_link_up(bool up) { impl_->link_up = up; }
ProcessDataIn Twin::pd_in() const { return decode_in(impl_->last_pd_in); }

IsduResult Twin::isdu_read(uint16_t index, uint8_t subindex) { return impl_->device.isdu_read(index, subindex); }

IsduResult Twin::isdu_write(uint16_t index, uint8_t subindex, std::span<const uint8_t> data) {
  Impl& s = *impl_;
  const ComPhase before = s.device.com_phase();
  IsduResult r = s.device.isdu_write(index, subindex, data);
  s.refresh_direction(); // index 82, or a reset to factory settings
  // A completed firmware update restarts the device (manual 9): the master
  // starts the port up again.
  if (before != ComPhase::Startup && s.device.com_phase() == ComPhase::Startup) {
    s.device_epoch_ns = s.time_ns; // the device's clock restarts with it
    s.startup_left = kStartupCycles;
  }
  return r;
}

void Twin::set_external_torque(double torque_Nm) { impl_->plant.set_external_torque(torque_Nm); }
void Twin::set_supply_voltage(double volts) { impl_->plant.set_supply_voltage(volts); }
void Twin::set_flange_blocked(bool blocked) { impl_->plant.set_flange_blocked(blocked); }
void Twin::set_load(const LoadSpec& load) {
  impl_->plant.set_load(load);
  impl_->config.load = load;
}
bool Twin::flange_blocked() const { return impl_->plant.flange_blocked(); }

void Twin::set_ambient_C(double celsius) { impl_->plant.set_ambient_C(celsius); }

void Twin::set_master_cycle_s(double cycle_s) {
  Impl& s = *impl_;
  s.steps = periods_per_cycle(cycle_s, s.config.module.drive.control_period_s()); // throws before anything changes
  s.cycle_s = cycle_s;
  s.config.cycle_s = cycle_s;
  s.cycle_ns = seconds_to_ns(cycle_s);
  s.device.set_master_cycle_time(cycle_s); // the master announces it (MasterCycleTime)
}

double Twin::master_cycle_s() const { return impl_->cycle_s; }

void Twin::power_off() {
  impl_->device.power_off();
  impl_->collect_moves();
}

void Twin::power_on() {
  Impl& s = *impl_;
  if (s.device.powered()) return;
  s.device.power_on(s.plant.sensors());
  s.device_epoch_ns = s.time_ns;
  s.startup_left = kStartupCycles;
  s.refresh_direction();
}

bool Twin::powered() const { return impl_->device.powered(); }

void Twin::power_cycle() {
  power_off();
  power_on();
}

void Twin::replace_device() {
  power_off();
  impl_->device = Device(firmware_drive(impl_->config.module.drive, impl_->config.nominal_motor)); // factory-new, as delivered ...
  impl_->device.power_off();    // ... and mounted unpowered
  power_on();
}

void Twin::turn_flange(double turn_deg, double over_s) {
  Impl& s = *impl_;
  const uint64_t n = over_s > 0 ? static_cast<uint64_t>(std::ceil(over_s / s.cycle_s - 1e-9)) : 0;
  const double start = s.plant.angle_rad();
  if (n == 0) {
    s.plant.set_flange_angle(start + deg_to_rad(turn_deg));
    return;
  }
  s.turning = true;
  s.turn_start_rad = start;
  s.turn_total_rad = deg_to_rad(turn_deg);
  s.turn_cycles = n;
  s.turn_done = 0;
}

void Twin::power_off_for(double off_s, double turn_deg) {
  power_off();
  turn_flange(turn_deg, off_s);
  const uint64_t n = off_s > 0 ? static_cast<uint64_t>(std::ceil(off_s / impl_->cycle_s - 1e-9)) : 0;
  for (uint64_t i = 0; i < n; ++i) run_cycle();
  power_on();
}

void Twin::run_cycle() {
  io::throw_if_interrupted(); // SIGINT / SIGTERM: unwind so outputs' temporaries go (issue 12)
  Impl& s = *impl_;
  const PdOutFrame out_frame = encode(s.pd_out);
  if (s.turning) { // a hand turns the flange evenly (manual 4.1)
    const double per_cycle = s.turn_total_rad / static_cast<double>(s.turn_cycles);
    const double at = s.turn_start_rad + per_cycle * static_cast<double>(s.turn_done);
    s.plant.set_flange_angle(at, per_cycle / s.cycle_s);
  }
  if (s.link_up && s.device.powered()) {
    // After a power-on the master wakes the device up and runs STARTUP and
    // PREOPERATE (no process data) before OPERATE (A-LINK-3).
    if (s.startup_left > 0) {
      const bool first = s.startup_left == kStartupCycles;
      if (first) s.device.set_master_cycle_time(s.cycle_s); // MasterCycleTime, written in STARTUP
      if (s.device.startup_cycle(first ? ComPhase::Startup : ComPhase::Preoperate)) --s.startup_left;
    } else if (const auto in = s.device.exchange(out_frame, s.outputs_valid)) {
      s.last_pd_in = *in;
    }
  }
  // The drive's clock (issue 25): one control step per period; the plant
  // sub-steps the physics inside it.
  const int64_t period_ns = s.config.module.drive.control_period_ns;
  for (int i = 0; i < s.steps; ++i) {
    s.ticked_counts = s.plant.sensors().encoder_counts;
    const MotorCommand cmd = s.device.tick_ns(period_ns, s.plant.sensors());
    s.plant.step(cmd);
  }
  if (s.turning && ++s.turn_done == s.turn_cycles) {
    s.turning = false;
    s.plant.set_flange_angle(s.turn_start_rad + s.turn_total_rad, 0.0); // exactly there, at rest
  }
  ++s.cycles;
  s.time_ns += s.cycle_ns;
  s.collect_moves();
  s.max_tracking_error_deg = std::max(s.max_tracking_error_deg, s.device.take_peak_tracking_error_deg());
  s.update_visuals();
  s.record_row(out_frame); // last_row() always; kept or streamed as configured
}

uint64_t Twin::cycles() const { return impl_->cycles; }
double Twin::time_s() const { return static_cast<double>(impl_->time_ns) * 1e-9; }
IoLinkLedMode Twin::iolink_led() const { return impl_->device.io_link_led(); }
Telemetry Twin::telemetry() const { return impl_->device.telemetry(); }
const std::vector<TraceRow>& Twin::trace() const { return impl_->trace; }
const TraceRow& Twin::last_row() const { return impl_->last_row; }
const std::vector<MoveRecord>& Twin::moves() const { return impl_->moves; }
double Twin::max_tracking_error_deg() const { return impl_->max_tracking_error_deg; }
double Twin::load_inertia_gcm2() const { return kgm2_to_gcm2(impl_->plant.load_inertia_kgm2()); }
const Device& Twin::device() const { return impl_->device; }
const Plant& Twin::plant() const { return impl_->plant; }
std::vector<uint8_t> Twin::save_nvm() const { return impl_->device.save_nvm(); }
TwinSnapshot Twin::snapshot() const {
  const Impl& s = *impl_;
  return TwinSnapshot{s.device.snapshot(), s.plant.snapshot(), static_cast<const TwinRunState&>(s), s.trace.size()};
}

// A-TWIN-34..36: the plant first (it throws on a different world, and then
// nothing has changed), then the device and the run.
void Twin::restore(const TwinSnapshot& snapshot) {
  Impl& s = *impl_;
  s.plant.restore(snapshot.plant);
  s.device.restore(snapshot.device);
  static_cast<TwinRunState&>(s) = snapshot.run;
  s.config.cycle_s = snapshot.run.cycle_s;
  s.config.load = snapshot.plant.world.load;
  if (s.trace.size() > snapshot.trace_rows) s.trace.resize(snapshot.trace_rows);
}

uint16_t Twin::firmware_update(std::span<const uint8_t> image) {
  for (const IsduWriteRequest& w : firmware_requests(image)) {
    for (uint64_t i = isdu_write_cycles(w.data.size()); i > 0; --i) run_cycle();
    const IsduResult r = isdu_write(w.index, w.subindex, w.data);
    if (!r.ok()) return r.error;
  }
  return 0;
}

} // namespace sreh
