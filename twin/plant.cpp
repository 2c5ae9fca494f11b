#include "twin/plant.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "device_logic/units.hpp"

namespace sreh {
namespace {
// -x beyond which exp(x) rounds to exactly 0 in double (exp(-745.14) is
// under half the least subnormal, 4.9e-324).
constexpr double kExpIsZeroBeyond = 746.0;

// Physics steps per control period (issue 25): the drive keeps its own
// clock, the simulator sub-steps it.
int substeps_per_period(const PlantConfig& c) {
  const double period_s = c.module.drive.control_period_s();
  if (!(c.physics_dt_s > 0.0) || !(period_s > 0.0)) {
    throw std::invalid_argument("physics_dt_s and the drive's control period must be positive");
  }
  const double ratio = period_s / c.physics_dt_s;
  const double rounded = std::round(ratio);
  if (rounded < 1 || std::abs(ratio - rounded) > 1e-9 * ratio) {
    throw std::invalid_argument("sim.physics_dt_s (" + std::to_string(c.physics_dt_s) +
                                " s) must divide the drive's control period (" + std::to_string(period_s) +
                                " s, model card control_period): the physics sub-steps the drive's clock");
  }
  return static_cast<int>(rounded);
}

int require_id(const mjModel* m, mjtObj type, const char* name, const std::string& file) {
  const int id = mj_name2id(m, type, name);
  if (id < 0) {
    throw std::invalid_argument(file + ": the module model has no element named \"" + name + "\"");
  }
  return id;
}

} // namespace

Plant::Plant(const PlantConfig& config)
    : drive_(config.module.drive.motor, firmware_drive(config.module.drive, config.nominal_motor).motor,
             config.module.drive.control_period_s(), config.physics_dt_s),
      supply_(config.supply, config.module.supply),
      thermal_(config.thermal, config.module.thermal),
      dt_s_(config.physics_dt_s),
      substeps_(substeps_per_period(config)),
      config_(config) {
  if (!std::isfinite(config.mounting_tilt_deg) || config.mounting_tilt_deg < -180.0 || config.mounting_tilt_deg > 180.0) {
    throw std::invalid_argument("mounting tilt_deg must be within -180 .. 180, got " + std::to_string(config.mounting_tilt_deg));
  }
  adopt_model(build_model(config.load, config.hard_stops, config.physics_dt_s, config.module.mechanics,
                          config.module_model_path, config.visual_detail));
  sensors_.encoder_counts = 0;
  sensors_.supply_V = supply_.bus_voltage_V();
  sensors_.temperature_C = thermal_.sensor_C();
  set_led_rgba(led_rgba(LedColor::Off));
}

// Takes over a compiled model: element ids, gravity from the mounting
// (A-TWIN-24), fresh data at the model's reference pose, inertias. The
// constructor's and set_load's common part (twin/plant_load.cpp).
void Plant::adopt_model(BuiltModel built) {
  model_ = std::move(built.model);
  load_inertia_kgm2_ = built.load_inertia_kgm2;
  axis_inertia_kgm2_ = built.axis_inertia_kgm2;
  mjModel* m = model_.get();
  const std::string& file = config_.module_model_path;
  const int rotor = require_id(m, mjOBJ_JOINT, "rotor", file);
  const int twist = require_id(m, mjOBJ_JOINT, "flange", file);
  rotor_qpos_ = m->jnt_qposadr[rotor];
  rotor_dof_ = m->jnt_dofadr[rotor];
  twist_qpos_ = m->jnt_qposadr[twist];
  twist_dof_ = m->jnt_dofadr[twist];
  actuator_ = require_id(m, mjOBJ_ACTUATOR, "motor", file);
  led_geom_ = mj_name2id(m, mjOBJ_GEOM, "led_band"); // the lean model has none (A-TWIN-42)
  // The lean model of a twin never drawn has no ghost (A-TWIN-42).
  const int ghost = mj_name2id(m, mjOBJ_BODY, "setpoint_ghost");
  ghost_mocap_ = ghost >= 0 ? m->body_mocapid[ghost] : -1;
  if (ghost >= 0 && ghost_mocap_ < 0) {
    throw std::invalid_argument(file + ": body \"setpoint_ghost\" must be a mocap body");
  }
  block_eq_ = mj_name2id(m, mjOBJ_EQUALITY, "flange_block"); // optional: stand-in models may lack it
  // A-TWIN-24: the module tilted about its x axis by T: in the module's
  // frame "down" is (0, -sin T, -cos T).
  const double tilt = deg_to_rad(config_.mounting_tilt_deg);
  const double g = std::sqrt(m->opt.gravity[0] * m->opt.gravity[0] + m->opt.gravity[1] * m->opt.gravity[1] +
                             m->opt.gravity[2] * m->opt.gravity[2]);
  m->opt.gravity[0] = 0.0;
  m->opt.gravity[1] = -g * std::sin(tilt);
  m->opt.gravity[2] = -g * std::cos(tilt);
  data_.reset(mj_makeData(m));
  mj_forward(m, data_.get());
  rotor_inertia_kgm2_ = m->dof_armature[rotor_dof_];
  twist_armature_kgm2_ = m->dof_armature[twist_dof_];
  flange_inertia_kgm2_ = data_->qM[m->dof_Madr[twist_dof_]];
}

double Plant::rotor_angle_rad() const { return data_->qpos[rotor_qpos_]; }
double Plant::rotor_velocity_rad_s() const { return data_->qvel[rotor_dof_]; }
double Plant::twist_rad() const { return data_->qpos[twist_qpos_]; }
double Plant::angle_rad() const { return data_->qpos[rotor_qpos_] + data_->qpos[twist_qpos_]; }
double Plant::velocity_rad_s() const { return data_->qvel[rotor_dof_] + data_->qvel[twist_dof_]; }
// A-TWIN-37: MuJoCo's Euler is semi-implicit (velocity first, then the
// position with the new velocity), so its position at the end of a step
// leads the motion's true position by v dt / 2: first-order in the step.
// The encoder sample takes that half step back, which makes the reading
// second-order accurate, so the drive does not see a delay that shrinks
// with the simulator's step (issue 25, docs/settling.md).
double Plant::rotor_angle_sampled_rad() const {
  return data_->qpos[rotor_qpos_] - 0.5 * dt_s_ * data_->qvel[rotor_dof_];
}

double Plant::stiffness_Nm_per_rad() const { return model_->jnt_stiffness[model_->dof_jntid[twist_dof_]]; }

double Plant::gravity_torque_Nm() const {
  // Generalised gravity force on the flange side (the twist dof carries all
  // of the flange and load): qfrc_bias holds -gravity (+ Coriolis, zero for
  // a fixed axis) as of the last forward pass.
  return -data_->qfrc_bias[twist_dof_];
}

// Cogging (A-TWIN-23): the drive-train effect MuJoCo's joint has no
// element for (the friction is the rotor joint's frictionloss and damping,
// set each step by set_drive_train_state).
double Plant::cogging_torque_Nm(double rotor_angle_rad) const {
  const MechanicsConstants& c = config_.module.mechanics;
  return c.cogging_torque_Nm * std::sin(c.cogging_periods_per_rev * rotor_angle_rad);
}

// The drive train's friction and gear for the coming step, from the state
// now (no state of their own). A-TWIN-22: the rotor's dry friction is
// MuJoCo's frictionloss constraint (it holds at rest up to its magnitude,
// whatever the step): Coulomb plus the Stribeck excess exp(-(w / w_s)^2),
// so the breakaway is Coulomb + excess and it fades with speed.
// A-TWIN-45 backlash: the spring's reference follows the twist inside the
// lost-motion band [-b/2, b/2], so the flanks transmit torque only beyond
// it (k (twist - clamp(twist, -b/2, b/2))), and the mesh damping acts
// only while the flanks touch. A-TWIN-46 efficiency: the rotor's Coulomb
// friction grows by (1 - efficiency) x the torque the flanks transmit.
void Plant::set_drive_train_state() {
  const MechanicsConstants& c = config_.module.mechanics;
  mjModel* m = model_.get();
  const double twist = data_->qpos[twist_qpos_];
  const double half_band = 0.5 * c.gear_backlash_rad;
  const double reference = std::clamp(twist, -half_band, half_band);
  const bool touching = half_band == 0.0 || std::abs(twist) > half_band;
  m->qpos_spring[twist_qpos_] = reference;
  apply_damping(touching ? c.torsional_damping_Nms_per_rad : 0.0, c.viscous_friction_Nms_per_rad);
  const double transmitted_Nm = c.torsional_stiffness_Nm_per_rad * (twist - reference);
  const double w = data_->qvel[rotor_dof_] / c.stribeck_speed_rad_s;
  // exp(x) is exactly 0 below x = -745.14 (under half the least subnormal),
  // where libm takes its slow underflow path: a moving rotor is far beyond.
  const double stribeck = w * w > kExpIsZeroBeyond ? 0.0 : std::exp(-w * w);
  m->dof_frictionloss[rotor_dof_] = c.coulomb_friction_Nm + c.stribeck_excess_Nm * stribeck +
                                    (1.0 - c.gear_efficiency) * std::abs(transmitted_Nm);
}

// A-TWIN-48: the mesh damping d and the rotor's drag b, integrated
// linearly implicitly, (M + h D) a = f - D v, as MuJoCo's Euler does with
// dof damping, but visible to its constraint solver: the force -D v goes in
// as an applied force and h D onto the mass matrix's diagonal (armature).
// MuJoCo 2.2's own dof damping is applied after the constraint forces were
// solved against M alone; with no load h d is 1.7 times the flange's own
// inertia, and the stiff equality of a blocked flange then gained energy
// each step until the numbers blew up (a flange jammed while moving).
void Plant::apply_damping(double twist_damping_Nms_per_rad, double rotor_damping_Nms_per_rad) {
  mjModel* m = model_.get();
  mjData* d = data_.get();
  const double h = m->opt.timestep;
  m->dof_damping[twist_dof_] = 0.0;
  m->dof_damping[rotor_dof_] = 0.0;
  m->dof_armature[twist_dof_] = twist_armature_kgm2_ + h * twist_damping_Nms_per_rad;
  m->dof_armature[rotor_dof_] = rotor_inertia_kgm2_ + h * rotor_damping_Nms_per_rad;
  d->qfrc_applied[twist_dof_] -= twist_damping_Nms_per_rad * d->qvel[twist_dof_];
  d->qfrc_applied[rotor_dof_] -= rotor_damping_Nms_per_rad * d->qvel[rotor_dof_];
}

const SensorReadings& Plant::step(const MotorCommand& cmd) {
  if (failed_) {
    throw std::runtime_error("plant: stepping after a MuJoCo failure");
  }
  const double omega = data_->qvel[rotor_dof_];
  const double bus_V = supply_.bus_voltage_V();
  const double sign = cmd.torque_Nm >= 0.0 ? 1.0 : -1.0;
  torque_limit_Nm_ = motor().max_torque_Nm(omega, bus_V, sign);
  drive_.control(cmd.torque_Nm, cmd.enabled, omega, bus_V); // the current loop: once per control period
  for (int i = 0; i < substeps_; ++i) physics_step(cmd.enabled);
  sensors_.encoder_counts = rad_to_internal_counts(rotor_angle_sampled_rad());
  sensors_.supply_V = supply_.bus_voltage_V();
  sensors_.temperature_C = thermal_.sensor_C();
  return sensors_;
}

// One physics sub-step with the period's bridge voltage.
void Plant::physics_step(bool enabled) {
  mjData* d = data_.get();
  const double omega = d->qvel[rotor_dof_];
  drive_.advance(omega);
  applied_torque_Nm_ = drive_.mean_torque_Nm();
  d->ctrl[actuator_] = applied_torque_Nm_;
  // An external torque acts on the flange: a generalised force on both
  // dofs (the flange angle is rotor + twist).
  d->qfrc_applied[rotor_dof_] = external_torque_Nm_ + cogging_torque_Nm(d->qpos[rotor_qpos_]);
  d->qfrc_applied[twist_dof_] = external_torque_Nm_;
  set_drive_train_state();
  try {
    mj_step(model_.get(), d);
  } catch (...) {
    failed_ = true; // the throwing warning handler fired inside mj_step
    throw;
  }
  check_warnings();
  ++steps_;

  // Electrical side over the step.
  copper_loss_W_ = drive_.mean_current_A() * drive_.mean_current_A() * motor().winding_resistance_ohm;
  // Bridge off: the winding's remaining current decays through the
  // freewheel diodes, drawing nothing from the bus.
  electrical_power_W_ = enabled ? applied_torque_Nm_ * omega + copper_loss_W_ : 0.0;
  supply_.step(dt_s_, electrical_power_W_);
  thermal_.step(dt_s_, copper_loss_W_ + thermal_.speed_loss_W(omega));
}

// A hand turns the whole drive train: rotor and flange together, no twist
// (A-TWIN-32); the winding current decays (the motor is off).
void Plant::set_flange_angle(double angle_rad, double velocity_rad_s) {
  mjData* d = data_.get();
  d->qpos[rotor_qpos_] = angle_rad;
  d->qpos[twist_qpos_] = 0.0;
  d->qvel[rotor_dof_] = velocity_rad_s;
  d->qvel[twist_dof_] = 0.0;
  mj_forward(model_.get(), d);
  drive_.reset();
  sensors_.encoder_counts = rad_to_internal_counts(angle_rad);
}

void Plant::check_warnings() {
  // 2.2.2 silently resets the data on bad numbers (mujoco.md): fatal here.
  static constexpr std::pair<int, const char*> kFatal[] = {
      {mjWARN_INERTIA, "singular inertia matrix"}, {mjWARN_BADQPOS, "bad number in qpos"},
      {mjWARN_BADQVEL, "bad number in qvel"},      {mjWARN_BADQACC, "bad number in qacc"},
      {mjWARN_BADCTRL, "bad number in ctrl"},
  };
  for (const auto& [index, what] : kFatal) {
    if (data_->warning[index].number > 0) {
      failed_ = true;
      throw std::runtime_error(std::string("plant: MuJoCo instability (") + what + ") at t = " +
                               std::to_string(time_s()) + " s");
    }
  }
}

void Plant::set_flange_blocked(bool blocked) {
  if (block_eq_ < 0) throw std::invalid_argument("plant: the module model has no equality \"flange_block\"");
  // Joint equality flange - (polycoef[0] - rotor) = 0: the flange's absolute
  // angle (rotor + twist) held at polycoef[0], here the angle now. Its force
  // acts on both joints as a torque on the flange body would.
  model_->eq_data[mjNEQDATA * block_eq_] = angle_rad();
  model_->eq_active[block_eq_] = blocked ? 1 : 0;
}

bool Plant::flange_blocked() const { return block_eq_ >= 0 && model_->eq_active[block_eq_] != 0; }

void Plant::set_led_rgba(const std::array<float, 4>& rgba) {
  led_rgba_ = rgba;
  if (led_geom_ < 0) return; // the lean model: nothing draws it
  float* dst = model_->geom_rgba + 4 * led_geom_;
  for (int i = 0; i < 4; ++i) dst[i] = rgba[static_cast<std::size_t>(i)];
}

void Plant::set_ghost_angle(double angle_rad) {
  ghost_angle_rad_ = angle_rad;
  if (ghost_mocap_ < 0) return; // the lean model: nothing draws it
  // Joint axis is -z: a flange angle q is a rotation by -q about world z.
  double* quat = data_->mocap_quat + 4 * ghost_mocap_;
  quat[0] = std::cos(-angle_rad / 2);
  quat[1] = 0;
  quat[2] = 0;
  quat[3] = std::sin(-angle_rad / 2);
}

std::array<float, 4> led_rgba(LedColor color) {
  switch (color) {
    case LedColor::Off: return {0.15f, 0.15f, 0.15f, 1.0f};
    case LedColor::Green: return {0.10f, 0.90f, 0.20f, 1.0f};
    case LedColor::Yellow: return {0.95f, 0.85f, 0.10f, 1.0f};
    case LedColor::Blue: return {0.15f, 0.35f, 1.00f, 1.0f};
    case LedColor::Red: return {1.00f, 0.10f, 0.08f, 1.0f};
    case LedColor::Orange: return {1.00f, 0.50f, 0.05f, 1.0f};
    case LedColor::White: return {0.95f, 0.95f, 0.95f, 1.0f};
    case LedColor::Violet: return {0.60f, 0.20f, 0.90f, 1.0f};
  }
  return {0.15f, 0.15f, 0.15f, 1.0f};
}

} // namespace sreh
