// Device: the public face (device.hpp). Each call hands the request to the
// firmware (Device::Impl) or reads one of its parts.
#include "device_logic/device.hpp"

#include <algorithm>

#include "device_logic/device_impl.hpp"

namespace sreh {

Device::Device(const DriveModel& drive) : impl_(std::make_unique<Impl>(drive)) { impl_->power_on(SensorReadings{}); }

Device::Device(const DriveModel& drive, const std::vector<uint8_t>& nvm_image) : impl_(std::make_unique<Impl>(drive)) {
  if (!restore_nvm(impl_->config, nvm_image)) {
    // A corrupt memory image: factory configuration and error 114.1 code 1 (A-NVM-1).
    impl_->power_on(SensorReadings{});
    impl_->raise_error(ErrorBit::DeviceError, cause::kInternalConfiguration);
    return;
  }
  impl_->power_on(SensorReadings{});
}

Device::Device(const DeviceSnapshot& snapshot) : impl_(std::make_unique<Impl>(snapshot)) {}

Device::~Device() = default;
Device::Device(const Device& other) : impl_(std::make_unique<Impl>(*other.impl_)) {}
Device& Device::operator=(const Device& other) {
  if (this != &other) *impl_ = *other.impl_;
  return *this;
}

DeviceSnapshot Device::snapshot() const { return impl_->snapshot(); }
void Device::restore(const DeviceSnapshot& snapshot) { *impl_ = Impl(snapshot); }

std::optional<PdInFrame> Device::exchange(const PdOutFrame& out, bool outputs_valid) {
  Impl& d = *impl_;
  if (!d.st.powered || d.st.comm_blocked) return std::nullopt;
  d.mon.link.feed();
  d.st.com_phase = ComPhase::Operate;
  if (!d.st.boot_mode) {
    if (outputs_valid) {
      d.st.last_out_frame = out;
      d.st.outputs_valid = true;
      d.process_outputs(decode_out(out));
    } else if (d.st.outputs_valid) {
      // Manual 5: valid -> invalid behaves like a connection interruption.
      d.st.outputs_valid = false;
      if (d.motor_on()) d.raise_error(ErrorBit::InvalidCommand, cause::kOutputsInvalid);
    }
  }
  d.st.last_in_frame = encode(pd_in(d.st, d.user_now()));
  return d.st.last_in_frame;
}

// dt_s becomes integer nanoseconds once, rounded to the nearest ns
// (units.hpp seconds_to_ns; negative or non-finite: 0).
MotorCommand Device::tick(double dt_s, const SensorReadings& sensors) {
  return impl_->tick(seconds_to_ns(dt_s), sensors);
}
MotorCommand Device::tick_ns(int64_t dt_ns, const SensorReadings& sensors) {
  return impl_->tick(std::max<int64_t>(dt_ns, 0), sensors);
}

IsduResult Device::isdu_read(uint16_t index, uint8_t subindex) { return impl_->read(index, subindex); }
IsduResult Device::isdu_write(uint16_t index, uint8_t subindex, std::span<const uint8_t> data) {
  return impl_->write(index, subindex, data);
}

void Device::power_off() {
  Impl& d = *impl_;
  d.config.store.abort_block();
  if (d.st.powered) { // a move in progress ends with the supply; a held one is handed out
    d.st.move_recorder.finish(d.st.time_ns, MoveOutcome::MotorOff, internal_counts_to_deg(d.user_now()));
    d.st.move_recorder.release();
  }
  d.st.powered = false;
}

double Device::take_peak_tracking_error_deg() { return impl_->mon.tracking.take_peak(); }

std::vector<MoveRecord> Device::take_finished_moves() { return impl_->st.move_recorder.take_finished(); }
std::optional<MoveRecord> Device::pending_move() const { return impl_->st.move_recorder.pending(); }
void Device::power_on(const SensorReadings& sensors) { impl_->power_on(sensors); }
bool Device::powered() const { return impl_->st.powered; }
bool Device::in_boot_mode() const { return impl_->st.boot_mode; }
LedColor Device::led() const { return led_color(impl_->st, impl_->mon.locator, impl_->config.store); }
std::vector<uint8_t> Device::save_nvm() const { return save_nvm_image(impl_->config); }

// Manual 1: Startup after every power-on until the master moves on;
// Operate also with the outputs marked invalid (DeviceOperate, manual 5:
// the device is in OPERATE then); off when the link is lost (A-LINK-3).
IoLinkLedMode Device::io_link_led() const {
  const Impl& d = *impl_;
  if (!d.st.powered || d.st.comm_blocked || !d.mon.link.link_up) return IoLinkLedMode::NotConnected;
  switch (d.st.com_phase) {
    case ComPhase::Startup: return IoLinkLedMode::Startup;
    case ComPhase::Preoperate: return IoLinkLedMode::Preoperate;
    case ComPhase::Operate: return IoLinkLedMode::Operate;
  }
  return IoLinkLedMode::NotConnected;
}

bool Device::startup_cycle(ComPhase phase) {
  Impl& d = *impl_;
  if (!d.st.powered || d.st.comm_blocked) return false;
  d.mon.link.feed();
  d.st.com_phase = phase == ComPhase::Operate ? ComPhase::Preoperate : phase; // OPERATE is exchange()
  return true;
}

ComPhase Device::com_phase() const { return impl_->st.com_phase; }

void Device::set_master_cycle_time(double cycle_s) { impl_->mon.link.master_cycle_ns = seconds_to_ns(cycle_s); }

Telemetry Device::telemetry() const {
  const Impl& d = *impl_;
  Telemetry t;
  const int dir = d.config.dir();
  t.state = d.st.state;
  t.position_deg = internal_counts_to_deg(d.user_now());
  t.setpoint_deg = d.setpoint_user_deg();
  t.tracking_error_deg = t.setpoint_deg - t.position_deg;
  t.velocity_dps = rad_to_deg(dir * d.st.velocity_rad_s);
  t.torque_Nm = d.motor_on() ? d.st.torque_Nm : 0.0;
  t.torque_limit_Nm = d.st.torque_limit_Nm;
  t.supply_V = d.st.supply_V;
  t.temperature_C = d.st.temperature_C;
  t.error_code = d.st.faults.error_byte();
  t.warning_code = d.st.faults.warning_byte();
  t.led = led_color(d.st, d.mon.locator, d.config.store);
  t.moving = d.st.state == State::Busy && d.st.phase == MotionPhase::Travel;
  t.settling = d.st.phase == MotionPhase::Settle;
  t.moves_started = d.st.moves_started;
  t.tolerance_deg = rad_to_deg(d.st.settle.tolerance_rad);
  return t;
}

} // namespace sreh
