// Plant::snapshot / restore (issue 13, A-TWIN-34, A-TWIN-35): the whole
// mjData by mj_copyData (MuJoCo resumes bit for bit from copied state,
// mujoco.md), plus what 2.2.2 keeps in mjModel and the twin changes while it
// runs: the flange block's eq_active / eq_data and the LED's colour.
#include <stdexcept>
#include <string>

#include "twin/plant.hpp"

namespace sreh {
namespace {

// The world a snapshot can go back into: everything but the load (restored)
// and the supply / thermal surroundings (their objects are restored whole).
std::string world_difference(const WorldSpec& now, const WorldSpec& then) {
  if (now.physics_dt_s != then.physics_dt_s) return "physics_dt_s";
  if (now.mounting_tilt_deg != then.mounting_tilt_deg) return "mounting tilt_deg";
  if (now.hard_stops != then.hard_stops) return "hard_stops";
  if (!(now.module == then.module)) return "model card";
  return {};
}

} // namespace

PlantSnapshot Plant::snapshot() const {
  if (failed_) throw std::runtime_error("plant: snapshot after a MuJoCo failure");
  std::shared_ptr<const mjData> copy(mj_copyData(nullptr, model_.get(), data_.get()), MjDataDeleter{});
  return PlantSnapshot{
      .world = config_,
      .data = std::move(copy),
      .flange_blocked = flange_blocked(),
      .block_angle_rad = block_eq_ >= 0 ? model_->eq_data[mjNEQDATA * block_eq_] : 0.0,
      .led_rgba = led_rgba_,
      .drive = drive_,
      .supply = supply_,
      .thermal = thermal_,
      .ghost_angle_rad = ghost_angle_rad_,
      .external_torque_Nm = external_torque_Nm_,
      .applied_torque_Nm = applied_torque_Nm_,
      .torque_limit_Nm = torque_limit_Nm_,
      .electrical_power_W = electrical_power_W_,
      .copper_loss_W = copper_loss_W_,
      .steps = steps_,
      .sensors = sensors_,
  };
}

void Plant::restore(const PlantSnapshot& s) {
  if (!s.data) throw std::invalid_argument("twin restore: the snapshot holds no plant state");
  if (const std::string what = world_difference(config_, s.world); !what.empty()) {
    throw std::invalid_argument("twin restore: the snapshot is of a twin with another " + what +
                                " (a snapshot goes back only into a twin made with the same world)");
  }
  // A-TWIN-34: the load the snapshot was taken with (set_load since, or
  // another twin's config): rebuilt, or nothing changes if it cannot be.
  auto check_fits = [&](const mjData* d) {
    if (d->nbuffer != s.data->nbuffer || d->nstack != s.data->nstack) {
      throw std::invalid_argument("twin restore: the snapshot's MuJoCo data does not fit this module model");
    }
  };
  if (!(s.world.load == config_.load)) {
    BuiltModel built = build_model(s.world.load, config_.hard_stops, dt_s_, config_.module.mechanics,
                                   config_.module_model_path, config_.visual_detail);
    check_fits(MjDataPtr(mj_makeData(built.model.get())).get());
    adopt_model(std::move(built));
    config_.load = s.world.load;
  } else {
    check_fits(data_.get());
  }
  mj_copyData(data_.get(), model_.get(), s.data.get());
  if (block_eq_ >= 0) { // a snapshot can be blocked only where the model has the equality
    model_->eq_data[mjNEQDATA * block_eq_] = s.block_angle_rad;
    model_->eq_active[block_eq_] = s.flange_blocked ? 1 : 0;
  }
  set_led_rgba(s.led_rgba);
  drive_ = s.drive;
  supply_ = s.supply;
  thermal_ = s.thermal;
  ghost_angle_rad_ = s.ghost_angle_rad;
  external_torque_Nm_ = s.external_torque_Nm;
  applied_torque_Nm_ = s.applied_torque_Nm;
  torque_limit_Nm_ = s.torque_limit_Nm;
  electrical_power_W_ = s.electrical_power_W;
  copper_loss_W_ = s.copper_loss_W;
  steps_ = s.steps;
  sensors_ = s.sensors;
  failed_ = false; // the snapshot was taken on a sound plant
}

} // namespace sreh
