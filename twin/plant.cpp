#include "twin/plant.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "device_logic/units.hpp"

namespace sreh {
namespace {

int require_id(const mjModel* m, mjtObj type, const char* name, const std::string& file) {
  const int id = mj_name2id(m, type, name);
  if (id < 0) {
    throw std::invalid_argument(file + ": the module model has no element named \"" + name + "\"");
  }
  return id;
}

} // namespace

Plant::Plant(const PlantConfig& config)
    : motor_(config.motor), supply_(config.supply), thermal_(config.thermal), dt_s_(config.physics_dt_s) {
  BuiltModel built = build_model(config.load, config.hard_stops, config.physics_dt_s, config.module_model_path);
  model_ = std::move(built.model);
  load_inertia_kgm2_ = built.load_inertia_kgm2;
  axis_inertia_kgm2_ = built.axis_inertia_kgm2;
  const mjModel* m = model_.get();
  const std::string& file = config.module_model_path;
  const int joint = require_id(m, mjOBJ_JOINT, "flange", file);
  qpos_adr_ = m->jnt_qposadr[joint];
  dof_adr_ = m->jnt_dofadr[joint];
  actuator_ = require_id(m, mjOBJ_ACTUATOR, "motor", file);
  led_geom_ = require_id(m, mjOBJ_GEOM, "led_band", file);
  ghost_mocap_ = m->body_mocapid[require_id(m, mjOBJ_BODY, "setpoint_ghost", file)];
  if (ghost_mocap_ < 0) {
    throw std::invalid_argument(file + ": body \"setpoint_ghost\" must be a mocap body");
  }
  data_.reset(mj_makeData(m));
  mj_forward(m, data_.get());
  sensors_.encoder_counts = 0;
  sensors_.supply_V = supply_.bus_voltage_V();
  sensors_.temperature_C = thermal_.sensor_C();
  set_led_rgba(led_rgba(LedColor::Off));
}

void Plant::set_flange_blocked(bool blocked) {
  if (blocked && !blocked_) blocked_angle_rad_ = data_->qpos[qpos_adr_];
  blocked_ = blocked;
  if (blocked_) {
    data_->qvel[dof_adr_] = 0;
    mj_forward(model_.get(), data_.get());
  }
}

double Plant::angle_rad() const { return data_->qpos[qpos_adr_]; }
double Plant::velocity_rad_s() const { return data_->qvel[dof_adr_]; }

const SensorReadings& Plant::step(const MotorCommand& cmd) {
  if (failed_) {
    throw std::runtime_error("plant: stepping after a MuJoCo failure");
  }
  mjData* d = data_.get();
  const double omega = d->qvel[dof_adr_];
  const double bus_V = supply_.bus_voltage_V();
  const double sign = cmd.torque_Nm >= 0.0 ? 1.0 : -1.0;
  torque_limit_Nm_ = motor_.max_torque_Nm(omega, bus_V, sign);
  applied_torque_Nm_ = cmd.enabled ? std::clamp(cmd.torque_Nm, -torque_limit_Nm_, torque_limit_Nm_) : 0.0;
  d->ctrl[actuator_] = applied_torque_Nm_;
  d->qfrc_applied[dof_adr_] = external_torque_Nm_;
  try {
    mj_step(model_.get(), d);
  } catch (...) {
    failed_ = true; // the throwing warning handler fired inside mj_step
    throw;
  }
  check_warnings();
  ++steps_;
  if (blocked_) { // the clamp takes whatever moved the flange
    d->qpos[qpos_adr_] = blocked_angle_rad_;
    d->qvel[dof_adr_] = 0;
  }

  // Electrical side with the torque held over the step (zero-order hold).
  copper_loss_W_ = motor_.copper_loss_W(applied_torque_Nm_);
  electrical_power_W_ = applied_torque_Nm_ * omega + copper_loss_W_;
  supply_.step(dt_s_, electrical_power_W_);
  thermal_.step(dt_s_, copper_loss_W_ + thermal_.speed_loss_W(omega));

  sensors_.encoder_counts = rad_to_internal_counts(d->qpos[qpos_adr_]);
  sensors_.supply_V = supply_.bus_voltage_V();
  sensors_.temperature_C = thermal_.sensor_C();
  return sensors_;
}

void Plant::set_flange_angle(double angle_rad, double velocity_rad_s) {
  mjData* d = data_.get();
  d->qpos[qpos_adr_] = angle_rad;
  d->qvel[dof_adr_] = velocity_rad_s;
  mj_forward(model_.get(), d);
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

void Plant::set_led_rgba(const std::array<float, 4>& rgba) {
  float* dst = model_->geom_rgba + 4 * led_geom_;
  for (int i = 0; i < 4; ++i) dst[i] = rgba[static_cast<std::size_t>(i)];
}

void Plant::set_ghost_angle(double angle_rad) {
  ghost_angle_rad_ = angle_rad;
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
