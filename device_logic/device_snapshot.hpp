// A whole Device as a value (issue 13): its configuration (non-volatile),
// its state (volatile) and its monitors. Device::snapshot() hands one out,
// Device::restore() takes one back; a restored device continues exactly as
// the original would, bit for bit. == compares everything observable (the
// ParameterStore's change counter aside, see parameter_store.hpp).
#pragma once

#include "device_logic/device_configuration.hpp"
#include "device_logic/device_monitors.hpp"
#include "device_logic/device_state.hpp"

namespace sreh {

struct DeviceSnapshot {
  DeviceConfiguration configuration;
  DeviceState state;
  DeviceMonitors monitors;
  bool operator==(const DeviceSnapshot&) const = default;
};

} // namespace sreh
