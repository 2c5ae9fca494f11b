// Compiled models kept for reuse (issue 31): a sweep builds a twin per run,
// but only a handful of different worlds (one per load). Compiling MJCF
// (mj_loadXML: parsing, the builtin textures, mj_setConst) is ~40 % of a
// sizing run's CPU time, while mj_copyModel of a compiled model is a copy of
// one buffer; the copy is bit for bit the model a fresh compile gives, so
// every result stays the same.
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "twin/load_builder.hpp"

namespace sreh {

// Everything a built model depends on (load_builder.cpp `build`): the
// composed MJCF text, its files, how much of it is kept for drawing, the
// physics step, the card's drive train. Content, not file names, so an
// edited load file is a new key.
struct ModelKey {
  std::string xml;
  std::vector<VfsFile> files;
  int detail = 0; // load_builder.cpp Detail: full, coarse textures, lean
  double physics_dt_s = 0;
  MechanicsConstants mechanics;
  bool operator==(const ModelKey&) const = default;
};

// At most this many models are kept (least recently used goes first): a
// model with the module's textures is ~2 MB.
inline constexpr std::size_t kModelCacheEntries = 24;

// A copy of the model built for `key` earlier in this process, if kept.
// Thread-safe.
std::optional<BuiltModel> cached_model(const ModelKey& key);

// The inertias of the model built for `key` earlier, without copying it.
struct ModelFigures {
  double load_inertia_kgm2 = 0;
  double axis_inertia_kgm2 = 0;
};
std::optional<ModelFigures> cached_figures(const ModelKey& key);

// Keeps a copy of `built` (a model that passed every check) for `key`.
void remember_model(ModelKey key, const BuiltModel& built);

// Drops every kept model (tests, benchmarks of a cold build).
void clear_model_cache();

} // namespace sreh
