// libFuzzer target: ISDU requests (manual chapter 6) on a factory-new device.
// The input is a sequence of requests: op (bit 0: write), index (2 bytes),
// subindex, length, data. Every answer is either data or an IO-Link error
// code; a write answered with an error leaves the device unchanged (its
// non-volatile memory image is the same before and after).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <vector>

#include "device_logic/device.hpp"
#include "device_logic/device_snapshot.hpp"
#include "twin/module_model.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  sreh::Device device{sreh::default_module_model().drive};
  const sreh::SensorReadings sensors{};
  std::size_t i = 0;
  int requests = 0;
  while (i + 5 <= size && requests++ < 64) {
    const uint8_t op = data[i];
    const uint16_t index = static_cast<uint16_t>(data[i + 1] << 8 | data[i + 2]);
    const uint8_t sub = data[i + 3];
    const std::size_t len = std::min<std::size_t>(data[i + 4], size - i - 5);
    const std::span<const uint8_t> payload(data + i + 5, len);
    i += 5 + len;
    if (op & 1) {
      // The device as a value (0.1 us). Its memory image follows from the
      // configuration, so it is made (6 us, most of this target's time when
      // done for every write) only when the configuration changed: a refused
      // write may discard an open transfer (download buffer, firmware chunks),
      // not change what is stored.
      const sreh::DeviceSnapshot before = device.snapshot();
      const sreh::IsduResult r = device.isdu_write(index, sub, payload);
      if (!r.ok() && (r.error & 0xFF00) != 0x8000) std::abort(); // error codes are 0x80xx
      if (!r.ok() && !(device.snapshot().configuration == before.configuration) &&
          sreh::Device(before).save_nvm() != device.save_nvm()) {
        std::abort(); // refused: the non-volatile memory is unchanged
      }
    } else {
      const sreh::IsduResult r = device.isdu_read(index, sub);
      if (!r.ok() && (!r.data.empty() || (r.error & 0xFF00) != 0x8000)) std::abort();
    }
    if (op & 2) device.tick(1e-4, sensors); // time passes between requests
  }
  return 0;
}
