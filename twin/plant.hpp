// The plant: everything outside the device's firmware that the twin
// simulates (issue 5): the MuJoCo flange with its load and world objects,
// the motor's physical torque limit, the supply and the thermal model.
// step(cmd) advances one physics step and returns the sensor readings the
// device sees next (encoder 2^19 counts/rev on the rotor, multiturn,
// physical frame: positive = clockwise seen from above).
// Issue 14: two masses (rotor with the encoder, flange with the load) on a
// torsional spring, the motor's current loop and winding (MotorDrive),
// bearing friction with a Stribeck rise, cogging, and gravity from the
// mounting orientation (docs/assumptions/twin.md A-TWIN-20..24); the
// gear's backlash and load-dependent loss (A-TWIN-45, -46). Every figure
// is referred to the output of the module's 8:1 gear (docs/model-card.md).
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "device_logic/device_types.hpp"
#include "device_logic/motor_model.hpp"
#include "twin/load_builder.hpp"
#include "twin/motor_drive.hpp"
#include "twin/mujoco_support.hpp"
#include "twin/supply.hpp"
#include "twin/thermal.hpp"
#include "twin/specs.hpp"
#include "twin/twin_snapshot.hpp"

namespace sreh {

// The plant's configuration: the world and the module's constants
// (twin/specs.hpp, shared with TwinConfig) plus the module's MJCF.
struct PlantConfig : WorldSpec {
  std::string module_model_path = default_module_model_path();
  // The module's textures at full size (renderers); false: coarse, for a
  // plant never drawn (sizing): a compile is ~7x faster and the model ~2 MB
  // smaller (issue 31). The physics is the same.
  bool visual_detail = true;
};

class Plant {
 public:
  explicit Plant(const PlantConfig& config); // throws std::invalid_argument on a bad load
  Plant(const Plant&) = delete;
  Plant& operator=(const Plant&) = delete;

  // One control period of the drive (issue 25): the torque reference goes
  // through the current loop (once per period) and the winding (the bus
  // voltage and back-EMF limit the current, so physics limits the torque
  // even if a controller did not); MuJoCo, supply and thermal advance in
  // control_period / physics_dt_s sub-steps. A MuJoCo instability
  // (bad qpos/qvel/qacc, singular inertia) throws std::runtime_error and
  // the plant stays failed.
  const SensorReadings& step(const MotorCommand& cmd);
  const SensorReadings& sensors() const { return sensors_; }

  void set_external_torque(double torque_Nm) { external_torque_Nm_ = torque_Nm; } // physical frame
  double external_torque_Nm() const { return external_torque_Nm_; }
  void set_ambient_C(double ambient_C) { thermal_.set_ambient_C(ambient_C); }
  // A clamp on the flange (fault injection, A-TWIN-30): a MuJoCo joint
  // equality holds the flange's absolute angle (rotor + twist) where it is
  // now; the rotor still winds the compliance against it and the motor
  // pushes with what it can give, so tracking errors come from the physics.
  void set_flange_blocked(bool blocked);
  bool flange_blocked() const;
  void set_supply_voltage(double volts) { supply_.set_source_voltage(volts); sensors_.supply_V = supply_.bus_voltage_V(); }
  // Puts the flange at `angle_rad` (physical frame) moving at `velocity_rad_s`,
  // as a hand turning it does (manual 4.1: moved while switched off): rotor
  // and flange together, no twist; the encoder reading follows at once. The
  // only place the plant's joint state is set from outside.
  void set_flange_angle(double angle_rad, double velocity_rad_s = 0.0);
  // A different load from now on (a gripper picks or releases a part,
  // A-TWIN-33, twin/plant_load.cpp): the model is rebuilt with `load` and
  // takes over the joint state (angles, speeds), the flange clamp, the LED
  // and ghost; motor drive, supply and thermal state go on unchanged.
  // Throws std::invalid_argument as the constructor does (nothing changes
  // then). model() and data() point to the new model afterwards.
  void set_load(const LoadSpec& load);
  // The plant as a value (twin/twin_snapshot.hpp, twin/plant_snapshot.cpp):
  // restore() rebuilds the model if the load differs (A-TWIN-34), throws
  // std::invalid_argument for another world (A-TWIN-35), no change then.
  PlantSnapshot snapshot() const;
  void restore(const PlantSnapshot& snapshot);

  // State, physical frame. The flange (output, where loads sit) and the
  // rotor (motor side, encoder) differ by the twist of the compliance.
  double angle_rad() const;             // flange
  double velocity_rad_s() const;        // flange
  double rotor_angle_rad() const;
  double rotor_velocity_rad_s() const;
  double rotor_angle_sampled_rad() const; // what the encoder samples at a period's end (A-TWIN-37)
  double twist_rad() const;             // flange - rotor
  double applied_torque_Nm() const { return applied_torque_Nm_; }   // motor torque (kt x winding current)
  double motor_current_A() const { return drive_.mean_current_A(); }
  double torque_limit_Nm() const { return torque_limit_Nm_; }       // capability in the commanded direction
  double gravity_torque_Nm() const;     // on the flange about the axis now (physical frame)
  double electrical_power_W() const { return electrical_power_W_; } // drawn from the bus (< 0 regenerating)
  double copper_loss_W() const { return copper_loss_W_; }
  uint64_t steps() const { return steps_; } // physics steps
  double time_s() const { return static_cast<double>(steps_) * dt_s_; } // integer clock, not d->time
  double physics_dt_s() const { return dt_s_; }
  int substeps() const { return substeps_; } // physics steps per control period

  double load_inertia_kgm2() const { return load_inertia_kgm2_; } // about the axis, from qM
  double axis_inertia_kgm2() const { return axis_inertia_kgm2_; } // incl. J_intern
  double rotor_inertia_kgm2() const { return rotor_inertia_kgm2_; }   // J_m
  double flange_inertia_kgm2() const { return flange_inertia_kgm2_; } // J_f + load
  double stiffness_Nm_per_rad() const;  // of the compliance between rotor and flange

  const Supply& supply() const { return supply_; }
  const Thermal& thermal() const { return thermal_; }
  const MotorModel& motor() const { return config_.module.drive.motor; }
  const ModuleModel& module() const { return config_.module; }

  // For renderers (renders/): the model and data; and the two visual hooks.
  const mjModel* model() const { return model_.get(); }
  mjData* data() { return data_.get(); }
  const mjData* data() const { return data_.get(); }
  void set_led_rgba(const std::array<float, 4>& rgba);   // geom "led_band" (if the model has it)
  const std::array<float, 4>& led_band_rgba() const { return led_rgba_; } // what set_led_rgba last set
  void set_ghost_angle(double angle_rad);                // mocap "setpoint_ghost" (if the model has it), physical frame
  double ghost_angle_rad() const { return ghost_angle_rad_; } // what set_ghost_angle last set

 private:
  void check_warnings();
  void adopt_model(BuiltModel built);
  double cogging_torque_Nm(double rotor_angle_rad) const;
  void physics_step(bool enabled);
  void set_drive_train_state();
  void apply_damping(double twist_damping_Nms_per_rad, double rotor_damping_Nms_per_rad);

  MjModelPtr model_;
  MjDataPtr data_;
  MotorDrive drive_;
  Supply supply_;
  Thermal thermal_;
  double dt_s_;
  int substeps_;
  PlantConfig config_; // the load, world and mounting it was built with (set_load rebuilds from it)
  int rotor_qpos_ = 0;   // joint "rotor": absolute rotor angle
  int rotor_dof_ = 0;
  int twist_qpos_ = 0;   // joint "flange": flange relative to the rotor
  int twist_dof_ = 0;
  int actuator_ = 0;
  int led_geom_ = -1;   // -1: no LED band (the lean model)
  int ghost_mocap_ = -1; // -1: no ghost (the lean model)
  int block_eq_ = -1; // equality "flange_block"
  double ghost_angle_rad_ = 0;
  std::array<float, 4> led_rgba_{};
  double load_inertia_kgm2_ = 0;
  double axis_inertia_kgm2_ = 0;
  double rotor_inertia_kgm2_ = 0;
  double flange_inertia_kgm2_ = 0;
  double twist_armature_kgm2_ = 0; // the module file's, before apply_damping
  double external_torque_Nm_ = 0;
  double applied_torque_Nm_ = 0;
  double torque_limit_Nm_ = 0;
  double electrical_power_W_ = 0;
  double copper_loss_W_ = 0;
  uint64_t steps_ = 0;
  bool failed_ = false;
  SensorReadings sensors_;
};

// LED band colour as RGBA for renderers (manual 3.1 colours).
std::array<float, 4> led_rgba(LedColor color);

} // namespace sreh
