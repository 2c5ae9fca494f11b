// The non-volatile part of the Device (manual 6.2 configuration, 6.3
// persistent diagnostics, 6.5 tags, 9 firmware-update state): what a power
// cycle keeps and the memory image carries (device_nvm.cpp).
#pragma once

#include "device_logic/drive_model.hpp"
#include "device_logic/parameter_ids.hpp"
#include "device_logic/parameter_store.hpp"

namespace sreh {

struct DeviceConfiguration {
  ParameterStore store;
  bool firmware_failed = false; // manual 9: a failed update starts in boot mode until a good image
  // The module's drive (model card): constant for the device's life, not in
  // the memory image (it is the hardware, not a stored parameter).
  DriveModel drive;

  // Manual 4.2, index 82: 1 = counter-clockwise is positive (-1 in the physical frame).
  int dir() const { return store.raw(param::kPositiveDirection) == 1 ? -1 : 1; }

  bool operator==(const DeviceConfiguration&) const = default;
};

} // namespace sreh
