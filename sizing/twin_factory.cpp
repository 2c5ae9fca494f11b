#include "sizing/twin_factory.hpp"

#include <algorithm>
#include <list>
#include <mutex>
#include <stdexcept>

#include "sizing/sizing.hpp"
#include "twin/twin_snapshot.hpp"

namespace sreh::sizing {

struct KeptTwin {
  TwinConfig config;
  std::unique_ptr<Twin> twin;
  TwinSnapshot fresh; // taken right after construction
};

namespace {

// Twins kept idle: a sweep point's runs share one world; the uncertainty
// samples each have their own; the searches' look-ahead runs come on
// threads of their own (search.cpp Speculation), so the pool is shared by
// all threads, not kept per thread: a per-thread pool built each look-ahead
// run's twin anew (model copy, mjData, device), issue 37.
constexpr std::size_t kKeptIdle = 6;

// Everything of a TwinConfig that make_twin's twin depends on.
// Every field of the world (WorldSpec's ==, so a field added there is
// compared too) and the cycle and trace settings the twin is built with.
bool same_world(const TwinConfig& a, const TwinConfig& b) {
  return static_cast<const WorldSpec&>(a) == static_cast<const WorldSpec&>(b) && a.cycle_s == b.cycle_s &&
         a.record_trace == b.record_trace && a.visual_detail == b.visual_detail && a.nvm_image == b.nvm_image;
}

struct Pool {
  std::mutex mutex;
  std::list<std::unique_ptr<KeptTwin>> idle; // most recently returned first
};

Pool& pool() {
  static Pool p;
  return p;
}

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

PooledTwin::PooledTwin(std::unique_ptr<KeptTwin> kept) : kept_(std::move(kept)) {}
PooledTwin::PooledTwin(PooledTwin&&) noexcept = default;

PooledTwin::~PooledTwin() {
  if (!kept_) return;
  Pool& p = pool();
  const std::lock_guard<std::mutex> lock(p.mutex);
  p.idle.push_front(std::move(kept_));
  if (p.idle.size() > kKeptIdle) p.idle.pop_back();
}

Twin& PooledTwin::operator*() const { return *kept_->twin; }

PooledTwin fresh_twin(const TwinConfig& config) {
  if (config.trace_sink || config.move_sink || config.nvm_image) {
    throw std::logic_error("fresh_twin: a config with sinks or a memory image is not kept");
  }
  std::unique_ptr<KeptTwin> kept;
  {
    Pool& p = pool();
    const std::lock_guard<std::mutex> lock(p.mutex);
    auto it = std::find_if(p.idle.begin(), p.idle.end(), [&](const auto& k) { return same_world(k->config, config); });
    if (it != p.idle.end()) {
      kept = std::move(*it);
      p.idle.erase(it);
    }
  }
  if (kept) {
    kept->twin->restore(kept->fresh); // outside the lock: threads restore in parallel
  } else {
    std::unique_ptr<Twin> twin = make_twin(config);
    TwinSnapshot fresh = twin->snapshot();
    kept.reset(new KeptTwin{config, std::move(twin), std::move(fresh)});
  }
  return PooledTwin(std::move(kept));
}

} // namespace sreh::sizing
