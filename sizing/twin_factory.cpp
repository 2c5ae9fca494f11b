#include "sizing/twin_factory.hpp"

#include <mutex>

#include "sizing/sizing.hpp"

namespace sreh::sizing {

std::unique_ptr<Twin> make_twin(const TwinConfig& config) {
  static std::mutex build_mutex;
  const std::lock_guard<std::mutex> lock(build_mutex);
  try {
    return std::make_unique<Twin>(config);
  } catch (const std::invalid_argument& e) {
    throw SizingInputError(e.what());
  }
}

} // namespace sreh::sizing
