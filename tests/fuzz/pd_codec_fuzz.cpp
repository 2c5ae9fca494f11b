// libFuzzer target: process data codec (manual 2.2 - 2.5). Any bytes: a
// frame of the wrong length is refused with std::invalid_argument; a frame of
// the right length decodes, and encode(decode(frame)) decodes to the same values.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <stdexcept>

#include "device_logic/process_data.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::span<const uint8_t> bytes(data, size);
  try {
    const sreh::ProcessDataOut out = sreh::decode_out(bytes);
    if (!(sreh::decode_out(sreh::encode(out)) == out)) std::abort();
  } catch (const std::invalid_argument&) {
  }
  try {
    const sreh::ProcessDataIn in = sreh::decode_in(bytes);
    if (!(sreh::decode_in(sreh::encode(in)) == in)) std::abort();
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
