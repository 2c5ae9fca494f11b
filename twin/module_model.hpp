// The module's physical constants as the twin uses them, filled from the
// model card (twin/model_card.hpp, models/sreh50-model.yaml): the drive the
// firmware knows (device_logic/drive_model.hpp) plus the plant's drive
// train, thermal and supply constants. Plain values; no defaults of their
// own (issue 25: nothing physical is a literal in code).
#pragma once
#include "device_logic/drive_model.hpp"

namespace sreh {

// Two masses on a spring with bearing friction and cogging (A-TWIN-4,
// A-TWIN-20..23): the motor side (rotor, encoder) and the output side
// (flange) of an 8:1 planetary gear, every figure referred to the output
// (docs/model-card.md "The drive layout"). The spring is the gear's
// torsional stiffness with its backlash as a lost-motion band
// (A-TWIN-45); the gear's load-dependent loss is friction on the rotor
// that grows with the torque it transmits (A-TWIN-46).
struct MechanicsConstants {
  double rotor_inertia_kgm2 = 0;          // J_m; the flange takes J_intern - J_m
  double torsional_stiffness_Nm_per_rad = 0;
  double torsional_damping_Nms_per_rad = 0;
  double coulomb_friction_Nm = 0;
  double viscous_friction_Nms_per_rad = 0;
  double stribeck_excess_Nm = 0;          // breakaway above Coulomb
  double stribeck_speed_rad_s = 0;
  double cogging_torque_Nm = 0;
  double cogging_periods_per_rev = 0;
  double gear_efficiency = 1;             // transmitted share of the torque through the gear (< 1)
  double gear_backlash_rad = 0;           // lost motion between rotor and flange, total
  bool operator==(const MechanicsConstants&) const = default;
};

// Two-node thermal model (A-TWIN-THERMAL-1, -2).
struct ThermalConstants {
  double winding_capacity_J_per_K = 0;    // winding + power stage hot spot the sensor sees
  double housing_capacity_J_per_K = 0;
  double winding_to_housing_K_per_W = 0;
  double housing_to_ambient_K_per_W = 0;
  double speed_loss_W_per_rad_s = 0;      // iron + bearing losses
  bool operator==(const ThermalConstants&) const = default;
};

// Supply (A-TWIN-11).
struct SupplyConstants {
  double bleed_resistance_ohm = 0;        // bus discharge through the electronics
  bool operator==(const SupplyConstants&) const = default;
};

struct ModuleModel {
  DriveModel drive;
  MechanicsConstants mechanics;
  ThermalConstants thermal;
  SupplyConstants supply;
  bool operator==(const ModuleModel&) const = default;
};

// The card in force when nothing else is given: models/sreh50-model.yaml,
// read once (thread-safe) from the models folder (twin/models_dir.hpp).
// Throws ModelCardError if it is missing or broken.
const ModuleModel& default_module_model();

} // namespace sreh
