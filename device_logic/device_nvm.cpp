// The non-volatile memory image (manual 6.2, 6.3, 9): a framed, versioned
// copy of the ParameterStore image plus the firmware-update state.
#include <algorithm>

#include "device_logic/data_storage.hpp"
#include "device_logic/device_impl.hpp"

namespace sreh {
namespace {
constexpr uint8_t kNvmMagic[4] = {'S', 'R', 'N', 'V'};
constexpr uint8_t kVersion = 1;
constexpr std::size_t kHeader = 6; // magic, version, firmware-failed flag
} // namespace

std::vector<uint8_t> save_nvm_image(const DeviceConfiguration& d) {
  std::vector<uint8_t> out(kNvmMagic, kNvmMagic + 4);
  out.push_back(kVersion);
  out.push_back(d.firmware_failed ? 1 : 0);
  const std::vector<uint8_t> store = d.store.image();
  out.insert(out.end(), store.begin(), store.end());
  return out;
}

bool restore_nvm(DeviceConfiguration& d, const std::vector<uint8_t>& image) {
  if (image.size() < kHeader || !std::equal(kNvmMagic, kNvmMagic + 4, image.begin()) || image[4] != kVersion ||
      image[5] > 1) {
    return false;
  }
  auto store = ParameterStore::from_image(std::span<const uint8_t>(image).subspan(kHeader));
  if (!store) return false;
  d.store = std::move(*store);
  d.firmware_failed = image[5] == 1;
  return true;
}

} // namespace sreh
