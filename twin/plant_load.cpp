// Plant::set_load (A-TWIN-33): a load change while the twin runs, as when
// a gripper on the flange picks up or releases a part. MuJoCo fixes a
// body's mass and inertia when the model is compiled, so the model is
// rebuilt with the new load and takes over the state of the old one.

#include "twin/plant.hpp"

namespace sreh {

void Plant::set_load(const LoadSpec& load) {
  // Build first: a load the module cannot carry throws and nothing changes.
  BuiltModel built = build_model(load, config_.hard_stops, dt_s_, config_.module.mechanics, config_.module_model_path,
                                 config_.visual_detail);
  const mjModel* old_m = model_.get();
  const mjData* old_d = data_.get();
  const double rotor_q = old_d->qpos[rotor_qpos_], twist_q = old_d->qpos[twist_qpos_];
  const double rotor_v = old_d->qvel[rotor_dof_], twist_v = old_d->qvel[twist_dof_];
  const bool blocked = flange_blocked();
  const double block_angle = block_eq_ >= 0 ? old_m->eq_data[mjNEQDATA * block_eq_] : 0.0;

  adopt_model(std::move(built));
  config_.load = load;
  // The part is gripped at rest in practice; the joint speeds are kept as
  // they are (a load taken on at speed would need an impact model).
  mjData* d = data_.get();
  d->qpos[rotor_qpos_] = rotor_q;
  d->qpos[twist_qpos_] = twist_q;
  d->qvel[rotor_dof_] = rotor_v;
  d->qvel[twist_dof_] = twist_v;
  if (blocked && block_eq_ >= 0) {
    model_->eq_data[mjNEQDATA * block_eq_] = block_angle;
    model_->eq_active[block_eq_] = 1;
  }
  set_led_rgba(led_rgba_);
  set_ghost_angle(ghost_angle_rad_);
  mj_forward(model_.get(), d);
}

} // namespace sreh
