// Builds the MuJoCo model of the module with one load and the world objects
// (issue 5): generates MJCF for each LoadSpec family, splices it into
// models/sreh50.xml at its "sreh:" markers and compiles it from memory.
// Refuses loads the module cannot carry with std::invalid_argument.
#pragma once
#include <string>
#include <vector>

#include "twin/mujoco_support.hpp"
#include "twin/module_model.hpp"
#include "twin/specs.hpp"

namespace sreh {

// Manual 6.2, index 64..71 subindex 4: the load row's maximum (15'000 g
// cm^2), read from the parameter table.
double max_load_gcm2();
// Smallest non-zero InertiaLoad: below it the modelled disk underflows (A-TWIN-5, issue 12).
inline constexpr double kMinInertiaGcm2 = 1e-6;

// A-TWIN-8: the limit holds within a relative tolerance, so a load of
// exactly 15000 g cm^2 (0.15 kg at 0.1 m) is accepted whatever MuJoCo's rounding.
bool within_load_limit(double load_gcm2);
// A figure in g cm^2 as messages print it: one decimal (21333.3, not 21333.333343333336).
std::string round_gcm2(double gcm2);

// models/sreh50.xml of this source tree.
std::string default_module_model_path();

// A short human-readable description, used in error messages.
std::string describe_load(const LoadSpec& load);

// The files a load reads (MJCF and mesh files, as resolved by the parser):
// an output must never be one of them.
std::vector<std::string> load_input_files(const LoadSpec& load);

// The MJCF text of the module with the load and world objects (deterministic).
// Throws std::invalid_argument for bad dimensions or a bad/missing load file.
struct ComposedModel {
  std::string xml;
  std::vector<VfsFile> files; // the loads' meshes, by the names the MJCF uses
};
ComposedModel compose_model(const LoadSpec& load, const std::vector<HardStop>& hard_stops,
                            const std::string& module_model_path = default_module_model_path());
std::string compose_model_xml(const LoadSpec& load, const std::vector<HardStop>& hard_stops,
                              const std::string& module_model_path = default_module_model_path());

struct BuiltModel {
  MjModelPtr model;
  double load_inertia_kgm2 = 0;   // about the flange axis, from MuJoCo's mass matrix
  double axis_inertia_kgm2 = 0;   // including J_intern (the joint armature)
};

// Composes, compiles (timestep = physics_dt_s, contacts only with hard stops)
// and checks the load: inertia about the axis <= 15'000 g cm^2, rigid (no
// joints of its own). Throws std::invalid_argument naming the load or file.
// The drive train's constants (rotor inertia, compliance, friction) come
// from the model card: `mechanics` (issue 25). Without `visual_detail` the
// module's textures are left coarse (a model that is never rendered).
BuiltModel build_model(const LoadSpec& load, const std::vector<HardStop>& hard_stops, double physics_dt_s,
                       const MechanicsConstants& mechanics = default_module_model().mechanics,
                       const std::string& module_model_path = default_module_model_path(),
                       bool visual_detail = true);

// build_model's load_inertia_kgm2 (after the same checks, the same
// exceptions), without a model to keep: from the model cache when the same
// world was built before (twin/model_cache.hpp), so a check costs no copy.
// Built with coarse textures, as a sizing twin is (one compile for both).
double built_load_inertia_kgm2(const LoadSpec& load, const std::vector<HardStop>& hard_stops, double physics_dt_s,
                               const MechanicsConstants& mechanics = default_module_model().mechanics,
                               const std::string& module_model_path = default_module_model_path());

// build_model with the model card's defaults, for checks and figures that
// never render: the module's textures are left coarse (7x faster to compile).
BuiltModel check_load(const LoadSpec& load);

// Inertia about the flange joint's axis incl. armature: qM at its dof after
// mj_forward (mujoco.md). Runs mj_forward on `data`.
double flange_axis_inertia_kgm2(const mjModel* model, mjData* data);

} // namespace sreh
