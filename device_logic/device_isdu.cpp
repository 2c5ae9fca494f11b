// ISDU routing of the Device (manual chapter 6): volatile diagnostics and
// the device-side system commands here, stored parameters in ParameterStore.
#include <algorithm>
#include <cmath>
#include <utility>

#include "device_logic/byte_order.hpp"
#include "device_logic/device_impl.hpp"
#include "device_logic/parameter_table.hpp"
#include "device_logic/position_frame.hpp"

namespace sreh {
namespace {

IsduResult number(ParamType type, int64_t value) { return isdu_data(encode_number(type, value)); }

// Manual 9: what a module in boot mode still answers besides 17343: the
// read-only identification of 6.5 (13..23, HW ID 17342), not the tags.
bool fixed_identification(uint16_t index) {
  const ParameterEntry* row = find_parameter(index, 0);
  return row != nullptr && row->storage == Storage::Identification && row->access == Access::R;
}

constexpr uint8_t kErrorAppears = 0xF4;
constexpr uint8_t kWarningAppears = 0xE4;

// Manual 6.4: Device Status (36) and Detailed Device Status (37) follow
// from the active faults alone.
uint8_t device_status(const FaultSet& faults) {
  if (faults.any_error()) return 4;   // failure
  if (faults.any_warning()) return 2; // out of specification
  return 0;
}

std::vector<uint8_t> detailed_device_status(const FaultSet& faults) {
  std::vector<uint8_t> out(12, 0); // OctetString3[4], manual 6.4
  std::size_t slot = 0;
  auto push = [&](uint8_t qualifier, uint16_t code) {
    if (slot >= 4) return;
    out[slot * 3] = qualifier;
    be::write(std::span<uint8_t>(out).subspan(slot * 3 + 1, 2), code);
    ++slot;
  };
  for (int bit = 7; bit >= 0; --bit) {
    if (faults.error_cause[bit]) push(kErrorAppears, kErrorEvents[bit].code); // A-EVT-1
  }
  if (faults.warning(WarningBit::Temperature)) push(kWarningAppears, kTemperatureWarningEvent.code);
  if (const uint8_t v = faults.warning(WarningBit::MotorVoltage)) {
    push(kWarningAppears, (v == cause::kVoltageLow ? kVoltageLowWarningEvent : kVoltageHighWarningEvent).code);
  }
  if (faults.warning(WarningBit::Positioning)) push(kWarningAppears, kToleranceWindowWarningEvent.code);
  return out;
}

} // namespace

IsduResult Device::Impl::read(uint16_t index, uint8_t sub) const {
  if (!st.powered || st.comm_blocked) return isdu_error(kIsduServiceTempUnavailable);
  if (index == Device::kFirmwareDataIndex) return isdu_error(kIsduAccessDenied); // write-only (A-FW-4)
  if (st.boot_mode && index != param::kBootModeStatus.index && !fixed_identification(index)) {
    return isdu_error(kIsduServiceTempUnavailable); // manual 9: normal functions disabled
  }
  auto plain = [&](ParamType type, int64_t value) {
    return sub == 0 ? number(type, value) : isdu_error(kIsduSubindexNotAvailable);
  };
  auto octets = [&](std::vector<uint8_t> bytes) {
    return sub == 0 ? isdu_data(std::move(bytes)) : isdu_error(kIsduSubindexNotAvailable);
  };
  switch (index) {
    case kIndexSystemCommand: return isdu_error(kIsduAccessDenied); // system command: write-only
    case param::kErrorCounter.index: return plain(ParamType::UInt16, st.error_counter);
    case param::kDeviceStatus.index: return plain(ParamType::UInt8, device_status(st.faults));
    case param::kDetailedDeviceStatus.index: return octets(detailed_device_status(st.faults));
    case param::kProcessDataInImage.index: return octets({st.last_in_frame.begin(), st.last_in_frame.end()});
    case param::kProcessDataOutImage.index: return octets({st.last_out_frame.begin(), st.last_out_frame.end()});
    case param::kTemperature.index: // raw 0.5 degC
      return plain(ParamType::UInt8, std::clamp<int64_t>(std::llround(st.temperature_C * 2.0), 0, 255));
    case param::kMotorVoltage.index: // raw mV
      return plain(ParamType::UInt16, std::clamp<int64_t>(std::llround(st.supply_V * 1000.0), 0, 65535));
    case param::kErrorCauses: {
      if (sub > 8) return isdu_error(kIsduSubindexNotAvailable);
      std::vector<uint8_t> all;
      for (int s = 1; s <= 8; ++s) all.push_back(st.faults.error_cause[8 - s]); // 114.1 = bit 7
      if (sub == 0) return isdu_data(all);
      return isdu_data({all[sub - 1]});
    }
    case param::kWarningCauses: {
      if (sub > 3) return isdu_error(kIsduSubindexNotAvailable);
      std::vector<uint8_t> all;
      for (int s = 1; s <= 3; ++s) all.push_back(st.faults.warning_cause[8 - s]); // 115.1 = bit 7
      if (sub == 0) return isdu_data(all);
      return isdu_data({all[sub - 1]});
    }
    case param::kBootModeStatus.index: {
      // During a transfer: boot mode; after a failed or interrupted one: 2 (A-FW-1).
      BootStatus boot = BootStatus::BootMode;
      if (!st.boot_mode) boot = BootStatus::Normal;
      else if (config.firmware_failed && st.fw_image.empty()) boot = BootStatus::BootModeAfterFailedUpdate;
      return plain(ParamType::UInt8, static_cast<int64_t>(boot));
    }
    default:
      return config.store.read(index, sub);
  }
}

IsduResult Device::Impl::write(uint16_t index, uint8_t sub, std::span<const uint8_t> data) {
  if (!st.powered || st.comm_blocked) return isdu_error(kIsduServiceTempUnavailable);
  if (index == kIndexSystemCommand) {
    if (sub != 0) return isdu_error(kIsduSubindexNotAvailable);
    if (data.size() > 1) return isdu_error(kIsduLengthOverrun);
    if (data.empty()) return isdu_error(kIsduLengthUnderrun);
    const uint16_t err = system_command(data[0]);
    return err ? isdu_error(err) : IsduResult{};
  }
  if (index == Device::kFirmwareDataIndex) {
    const uint16_t err = firmware_write(sub, data);
    return err ? isdu_error(err) : IsduResult{};
  }
  if (st.boot_mode) return isdu_error(kIsduServiceTempUnavailable);
  switch (index) { // volatile diagnostics are read-only
    case param::kErrorCounter.index: case param::kDeviceStatus.index: case param::kDetailedDeviceStatus.index:
    case param::kProcessDataInImage.index: case param::kProcessDataOutImage.index: case param::kTemperature.index:
    case param::kMotorVoltage.index: case param::kErrorCauses: case param::kWarningCauses:
    case param::kBootModeStatus.index:
      return isdu_error(kIsduAccessDenied);
    default:
      break;
  }
  const int64_t zero_before = config.store.raw(param::kPositionZero);
  IsduResult r = config.store.write(index, sub, data);
  // Manual 4.3.2 / 4.3.3: writing index 86 stores the zero offset and applies
  // it, also when it arrives through a Data Storage download (index 3).
  const bool zero_written = index == param::kPositionZero.index && !config.store.download_open();
  if (r.ok() && (zero_written || config.store.raw(param::kPositionZero) != zero_before)) init_origin();
  if (r.ok() && motor_on() && st.phase == MotionPhase::Hold) { // A-SM-6: its load may have changed
    tune_for_set(st, config.store, st.hold_set);
  }
  return r;
}

// Manual 6.6.
uint16_t Device::Impl::system_command(uint8_t cmd) {
  if (st.boot_mode && !(cmd >= 80 && cmd <= 82)) return kIsduFunctionTempUnavailable;
  switch (cmd) {
    case 1: case 2: case 3: case 4: case 5: case 6: { // block parameterisation
      const int64_t zero_before = config.store.raw(param::kPositionZero);
      const uint16_t err = config.store.block_command(cmd);
      // A downloaded 86 is applied.
      if (err == 0 && config.store.raw(param::kPositionZero) != zero_before) init_origin();
      return err;
    }
    case 80: // firmware update unlock, step 1 (A-FW-2)
      st.fw_unlock_step = 1;
      return 0;
    case 81:
      if (st.fw_unlock_step != 1) return kIsduFunctionTempUnavailable;
      st.fw_unlock_step = 2;
      return 0;
    case 82: // enter boot mode (manual 9): normal functions off, configuration kept
      if (st.fw_unlock_step != 2) return kIsduFunctionTempUnavailable;
      st.fw_unlock_step = 0;
      if (motor_on()) enter(State::MotorOff, Event::SwitchOff);
      st.state = State::MotorOff;
      st.boot_mode = true;
      mon.locator.stop();
      return 0;
    case 126: // Locator start
      mon.locator.start(st.time_ns);
      return 0;
    case 127: // Locator stop
      mon.locator.stop();
      return 0;
    case 129: // Application reset: configuration to factory settings
    case 131: { // Back-To-Box: the same, then silent until power is cycled
      config.store.factory_reset(/*keep_tags=*/cmd == 129);
      init_origin();
      if (cmd == 131) st.comm_blocked = true;
      return 0;
    }
    case 160: // reset the resettable maximum temperature (index 99)
      config.store.set_raw_internal(param::kMaxTemperatureResettable.operating_time, 0);
      config.store.set_raw_internal(param::kMaxTemperatureResettable.temperature, 0);
      return 0;
    case 161: // reset the time above critical temperature (index 100)
      config.store.set_raw_internal(param::kTimeWithTemperatureWarning, 0);
      mon.diagnostics.temp_warn_rem_ns = 0;
      return 0;
    case 170: // apply position zero: re-initialise from index 86 (manual 4.3.3)
      init_origin();
      return 0;
    case 171: // store the zero set with Set Origin persistently (manual 4.3.2)
      config.store.set_raw_internal(param::kPositionZero, origin_to_zero_offset_wire(st.origin));
      return 0;
    default:
      return kIsduFunctionUnavailable;
  }
}

} // namespace sreh
