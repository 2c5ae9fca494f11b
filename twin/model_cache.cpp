#include "twin/model_cache.hpp"

#include <algorithm>
#include <functional>
#include <list>
#include <memory>
#include <mutex>

namespace sreh {
namespace {

struct Entry {
  std::size_t hash = 0;
  ModelKey key;
  std::shared_ptr<const mjModel> model; // never modified: copies are handed out
  double load_inertia_kgm2 = 0;
  double axis_inertia_kgm2 = 0;
};

struct Cache {
  std::mutex mutex;
  std::list<Entry> entries; // most recently used first
};

Cache& cache() {
  static Cache c;
  return c;
}

std::size_t hash_of(const ModelKey& key) {
  std::size_t h = std::hash<std::string>{}(key.xml);
  for (const VfsFile& f : key.files) h = h * 31 + std::hash<std::string>{}(f.bytes);
  h = h * 31 + static_cast<std::size_t>(key.detail);
  return h;
}

MjModelPtr copy_of(const mjModel* model) { return MjModelPtr(mj_copyModel(nullptr, model)); }

// The entry for `key`, moved to the front; nullopt if not kept.
std::optional<Entry> find(const ModelKey& key) {
  const std::size_t h = hash_of(key);
  Cache& c = cache();
  const std::lock_guard<std::mutex> lock(c.mutex);
  auto it = std::find_if(c.entries.begin(), c.entries.end(), [&](const Entry& e) { return e.hash == h && e.key == key; });
  if (it == c.entries.end()) return std::nullopt;
  c.entries.splice(c.entries.begin(), c.entries, it);
  Entry e;
  e.model = it->model; // shared: the key is not needed by the callers
  e.load_inertia_kgm2 = it->load_inertia_kgm2;
  e.axis_inertia_kgm2 = it->axis_inertia_kgm2;
  return e;
}

} // namespace

std::optional<BuiltModel> cached_model(const ModelKey& key) {
  std::optional<Entry> e = find(key);
  if (!e) return std::nullopt;
  BuiltModel built;
  built.model = copy_of(e->model.get()); // outside the lock: threads copy in parallel
  built.load_inertia_kgm2 = e->load_inertia_kgm2;
  built.axis_inertia_kgm2 = e->axis_inertia_kgm2;
  return built;
}

std::optional<ModelFigures> cached_figures(const ModelKey& key) {
  std::optional<Entry> e = find(key);
  if (!e) return std::nullopt;
  return ModelFigures{e->load_inertia_kgm2, e->axis_inertia_kgm2};
}

void remember_model(ModelKey key, const BuiltModel& built) {
  Entry e;
  e.hash = hash_of(key);
  e.key = std::move(key);
  e.model = std::shared_ptr<const mjModel>(copy_of(built.model.get()).release(), MjModelDeleter{});
  e.load_inertia_kgm2 = built.load_inertia_kgm2;
  e.axis_inertia_kgm2 = built.axis_inertia_kgm2;
  Cache& c = cache();
  const std::lock_guard<std::mutex> lock(c.mutex);
  const std::size_t h = e.hash;
  const auto same = [&](const Entry& x) { return x.hash == h && x.key == e.key; };
  if (std::any_of(c.entries.begin(), c.entries.end(), same)) return; // another thread was first
  c.entries.push_front(std::move(e));
  if (c.entries.size() > kModelCacheEntries) c.entries.pop_back();
}

void clear_model_cache() {
  Cache& c = cache();
  const std::lock_guard<std::mutex> lock(c.mutex);
  c.entries.clear();
}

} // namespace sreh
