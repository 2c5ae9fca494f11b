#include "sizing/twin_factory.hpp"

#include <algorithm>
#include <list>
#include <mutex>
#include <stdexcept>

#include "sizing/sizing.hpp"
#include "twin/twin_snapshot.hpp"

namespace sreh::sizing {
namespace {

// Twins kept per thread: a sweep point's runs share one world; the
// uncertainty samples each have their own.
constexpr std::size_t kKeptPerThread = 3;

// Everything of a TwinConfig that make_twin's twin depends on.
// Every field of the world (WorldSpec's ==, so a field added there is
// compared too) and the cycle and trace settings the twin is built with.
bool same_world(const TwinConfig& a, const TwinConfig& b) {
  return static_cast<const WorldSpec&>(a) == static_cast<const WorldSpec&>(b) && a.cycle_s == b.cycle_s &&
         a.record_trace == b.record_trace && a.visual_detail == b.visual_detail && a.nvm_image == b.nvm_image;
}

struct Kept {
  TwinConfig config;
  std::unique_ptr<Twin> twin;
  TwinSnapshot fresh; // taken right after construction
};

} // namespace

std::unique_ptr<Twin> make_twin(const TwinConfig& config) {
  static std::mutex build_mutex;
  const std::lock_guard<std::mutex> lock(build_mutex);
  try {
    return std::make_unique<Twin>(config);
  } catch (const std::invalid_argument& e) {
    throw SizingInputError(e.what());
  }
}

Twin& fresh_twin(const TwinConfig& config) {
  if (config.trace_sink || config.move_sink || config.nvm_image) {
    throw std::logic_error("fresh_twin: a config with sinks or a memory image is not kept");
  }
  thread_local std::list<Kept> kept; // most recently used first
  auto it = std::find_if(kept.begin(), kept.end(), [&](const Kept& k) { return same_world(k.config, config); });
  if (it != kept.end()) {
    kept.splice(kept.begin(), kept, it);
    kept.front().twin->restore(kept.front().fresh);
    return *kept.front().twin;
  }
  std::unique_ptr<Twin> twin = make_twin(config);
  TwinSnapshot fresh = twin->snapshot();
  kept.push_front(Kept{config, std::move(twin), std::move(fresh)});
  if (kept.size() > kKeptPerThread) kept.pop_back();
  return *kept.front().twin;
}

} // namespace sreh::sizing
