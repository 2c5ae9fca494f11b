// What the world around the module is made of (issue 5): the load, hard
// stops, supply, thermal surroundings and mounting. Plain values, shared by
// the plant (twin/plant.hpp) and the twin (twin/twin.hpp); the lower twin
// headers (supply, thermal, load_builder) need only this one.
#pragma once
#include <array>
#include <string>
#include <variant>
#include <vector>

#include "twin/firmware_motor.hpp"
#include "twin/module_model.hpp"

namespace sreh {

// Attachable loads (issue 5). Masses in kg, lengths in m.
struct DiskLoad { double mass_kg = 0; double radius_m = 0; double thickness_m = 0.01;
  bool operator==(const DiskLoad&) const = default; };
struct RingLoad { double mass_kg = 0; double inner_radius_m = 0; double outer_radius_m = 0; double thickness_m = 0.01;
  bool operator==(const RingLoad&) const = default; };
struct BoxLoad { double mass_kg = 0; double x_m = 0; double y_m = 0; double z_m = 0;
  bool operator==(const BoxLoad&) const = default; };
// A light arm (its own mass spread along it) with a point mass at `radius_m`.
struct ArmLoad { double mass_kg = 0; double radius_m = 0; double arm_mass_kg = 0;
  bool operator==(const ArmLoad&) const = default; };
struct InertiaLoad { double inertia_gcm2 = 0; bool operator==(const InertiaLoad&) const = default; }; // a given inertia about the axis
struct MjcfLoad { std::string path; bool operator==(const MjcfLoad&) const = default; }; // any MJCF body file
struct NoLoad { bool operator==(const NoLoad&) const = default; };

// Part shapes of an assembly (issue 28), each centred on its part frame.
struct CylinderPart { double mass_kg = 0; double radius_m = 0; double length_m = 0; // solid, axis along the part's z
  bool operator==(const CylinderPart&) const = default; };
struct SpherePart { double mass_kg = 0; double radius_m = 0; bool operator==(const SpherePart&) const = default; };
struct PointPart { double mass_kg = 0; bool operator==(const PointPart&) const = default; }; // a point mass
// An STL file (ASCII or binary), path as resolved by the parser; mass_kg or
// density_kg_m3 (the other 0); the file's coordinates times `scale` are metres.
struct MeshPart { std::string path; double mass_kg = 0; double density_kg_m3 = 0; double scale = 1;
  bool operator==(const MeshPart&) const = default; };
using PartShape = std::variant<DiskLoad, RingLoad, BoxLoad, CylinderPart, SpherePart, PointPart, MeshPart, MjcfLoad>;

// One part: its shape, placed with its centre (a mesh's or MJCF's own
// origin) at `at_m` in the flange frame (z up from the mounting face, x
// toward flange angle 0) and turned by roll, pitch, yaw about the flange's
// fixed x, y, z axes in that order (A-TWIN-39). `origin` names the part in
// messages ("FILE:LINE:COL").
struct LoadPart {
  PartShape shape;
  std::array<double, 3> at_m{};
  std::array<double, 3> rpy_deg{};
  std::string origin;
  std::string name; // the user's name for it (`name:`), shown by `load show`
  bool operator==(const LoadPart&) const = default;
};
struct AssemblyLoad { std::vector<LoadPart> parts; std::string origin; bool operator==(const AssemblyLoad&) const = default; };

using LoadSpec = std::variant<NoLoad, DiskLoad, RingLoad, BoxLoad, ArmLoad, InertiaLoad, MjcfLoad, AssemblyLoad>;

// Optional world objects.
struct HardStop { double angle_deg = 0; bool operator==(const HardStop&) const = default; }; // an obstacle the load hits at this flange angle

struct SupplySpec {
  double voltage_V = 24.0;            // source voltage
  double source_resistance_ohm = 0.0; // 0: ideal source
  double bus_capacitance_F = 0.0;     // with resistance > 0: bus voltage dynamics
  bool operator==(const SupplySpec&) const = default;
};

struct ThermalSpec {
  double ambient_C = 25.0;
  double time_scale = 1.0; // > 1 accelerates thermal dynamics (documented, for long duty tests)
  bool operator==(const ThermalSpec&) const = default;
};

// The world and the physics step: written once here, the base of both
// PlantConfig (adds the motor and the module's MJCF) and TwinConfig (adds
// the IO-Link cycle, memory and trace handling).
struct WorldSpec {
  LoadSpec load = NoLoad{};
  std::vector<HardStop> hard_stops;
  SupplySpec supply;
  ThermalSpec thermal;
  // Mounting (A-TWIN-24): tilt of the module's axis from vertical, degrees.
  // 0 = axis vertical (flange up, default), 90 = axis horizontal with the
  // module's +y pointing up, so a load along +x at flange angle 0 feels the
  // largest gravity torque (m g r cos(angle)).
  double mounting_tilt_deg = 0.0;
  // The physics step: divides the drive's control period (the model card's
  // control_period), which it sub-steps (issue 25); only numerical error
  // depends on it.
  double physics_dt_s = 1e-4;
  // The module's constants: the model card (twin/model_card.hpp), with any
  // --model overrides applied.
  ModuleModel module = default_module_model();
  // The motor constants the firmware was built for (issue 36, A-CAL-11):
  // the shipped card's, whatever `module` says (twin/firmware_motor.hpp).
  NominalMotor nominal_motor = nominal_motor_of(default_module_model().drive.motor);
  bool operator==(const WorldSpec&) const = default;
};

} // namespace sreh
