#include "twin/model_lean.hpp"

#include <cstring>
#include <regex>

namespace sreh {
namespace {

// Arrays of n rows of `width` elements, equal bit for bit.
template <class T>
bool same_rows(const T* a, const T* b, int n, int width = 1) {
  return n == 0 || std::memcmp(a, b, sizeof(T) * static_cast<std::size_t>(n) * static_cast<std::size_t>(width)) == 0;
}

bool same_tree(const mjModel* a, const mjModel* b) {
  if (a->nbody != b->nbody || a->njnt != b->njnt || a->nq != b->nq || a->nv != b->nv || a->nu != b->nu ||
      a->neq != b->neq || a->nM != b->nM || a->nmocap != b->nmocap) {
    return false;
  }
  const int n = a->nbody;
  return same_rows(a->body_parentid, b->body_parentid, n) && same_rows(a->body_rootid, b->body_rootid, n) &&
         same_rows(a->body_weldid, b->body_weldid, n) && same_rows(a->body_mocapid, b->body_mocapid, n) &&
         same_rows(a->body_jntnum, b->body_jntnum, n) && same_rows(a->body_jntadr, b->body_jntadr, n) &&
         same_rows(a->body_dofnum, b->body_dofnum, n) && same_rows(a->body_dofadr, b->body_dofadr, n) &&
         same_rows(a->body_pos, b->body_pos, n, 3) && same_rows(a->body_quat, b->body_quat, n, 4);
}

// Inertials of the bodies that move (welded to a joint, not to the world).
bool same_inertials(const mjModel* a, const mjModel* b) {
  for (int i = 0; i < a->nbody; ++i) {
    if (a->body_weldid[i] == 0) continue; // the world and what is welded to it: no dynamics
    if (!same_rows(a->body_mass + i, b->body_mass + i, 1) || !same_rows(a->body_subtreemass + i, b->body_subtreemass + i, 1) ||
        !same_rows(a->body_inertia + 3 * i, b->body_inertia + 3 * i, 1, 3) ||
        !same_rows(a->body_ipos + 3 * i, b->body_ipos + 3 * i, 1, 3) ||
        !same_rows(a->body_iquat + 4 * i, b->body_iquat + 4 * i, 1, 4)) {
      return false;
    }
  }
  return true;
}

bool same_joints(const mjModel* a, const mjModel* b) {
  const int j = a->njnt, v = a->nv;
  return same_rows(a->jnt_type, b->jnt_type, j) && same_rows(a->jnt_qposadr, b->jnt_qposadr, j) &&
         same_rows(a->jnt_dofadr, b->jnt_dofadr, j) && same_rows(a->jnt_bodyid, b->jnt_bodyid, j) &&
         same_rows(a->jnt_limited, b->jnt_limited, j) && same_rows(a->jnt_pos, b->jnt_pos, j, 3) &&
         same_rows(a->jnt_axis, b->jnt_axis, j, 3) && same_rows(a->jnt_stiffness, b->jnt_stiffness, j) &&
         same_rows(a->jnt_range, b->jnt_range, j, 2) && same_rows(a->jnt_solref, b->jnt_solref, j, mjNREF) &&
         same_rows(a->jnt_solimp, b->jnt_solimp, j, mjNIMP) && same_rows(a->qpos0, b->qpos0, a->nq) &&
         same_rows(a->qpos_spring, b->qpos_spring, a->nq) && same_rows(a->dof_bodyid, b->dof_bodyid, v) &&
         same_rows(a->dof_jntid, b->dof_jntid, v) && same_rows(a->dof_parentid, b->dof_parentid, v) &&
         same_rows(a->dof_Madr, b->dof_Madr, v) && same_rows(a->dof_armature, b->dof_armature, v) &&
         same_rows(a->dof_damping, b->dof_damping, v) && same_rows(a->dof_frictionloss, b->dof_frictionloss, v) &&
         same_rows(a->dof_invweight0, b->dof_invweight0, v) && same_rows(a->dof_M0, b->dof_M0, v) &&
         same_rows(a->dof_solref, b->dof_solref, v, mjNREF) && same_rows(a->dof_solimp, b->dof_solimp, v, mjNIMP);
}

bool same_actuators_and_equalities(const mjModel* a, const mjModel* b) {
  const int u = a->nu, e = a->neq;
  return same_rows(a->actuator_trntype, b->actuator_trntype, u) && same_rows(a->actuator_trnid, b->actuator_trnid, u, 2) &&
         same_rows(a->actuator_dyntype, b->actuator_dyntype, u) && same_rows(a->actuator_gaintype, b->actuator_gaintype, u) &&
         same_rows(a->actuator_biastype, b->actuator_biastype, u) && same_rows(a->actuator_gear, b->actuator_gear, u, 6) &&
         same_rows(a->actuator_gainprm, b->actuator_gainprm, u, mjNGAIN) &&
         same_rows(a->actuator_biasprm, b->actuator_biasprm, u, mjNBIAS) &&
         same_rows(a->actuator_ctrllimited, b->actuator_ctrllimited, u) &&
         same_rows(a->actuator_ctrlrange, b->actuator_ctrlrange, u, 2) && same_rows(a->actuator_length0, b->actuator_length0, u) &&
         same_rows(a->eq_type, b->eq_type, e) && same_rows(a->eq_obj1id, b->eq_obj1id, e) &&
         same_rows(a->eq_obj2id, b->eq_obj2id, e) && same_rows(a->eq_active, b->eq_active, e) &&
         same_rows(a->eq_data, b->eq_data, e, mjNEQDATA) && same_rows(a->eq_solref, b->eq_solref, e, mjNREF) &&
         same_rows(a->eq_solimp, b->eq_solimp, e, mjNIMP);
}

} // namespace

std::string without_drawing_geoms(const std::string& xml) {
  static const std::regex drawing(
      R"re(<geom\s+name="(table|floor_[nsew]|plate|housing|connector|collar|flange|bore|mark|stop_lug|ghost_pointer|ghost_tip)"[^>]*/>)re");
  // Lights and cameras too: mj_camlight places them in every step (~4 % of
  // a sizing run's CPU time, issue 37); nothing else in mj_step reads them.
  static const std::regex light_or_camera(R"re(<(light|camera)\s[^>]*/>)re");
  return std::regex_replace(std::regex_replace(xml, drawing, ""), light_or_camera, "");
}

bool same_dynamics(const mjModel* a, const mjModel* b) {
  return same_tree(a, b) && same_inertials(a, b) && same_joints(a, b) && same_actuators_and_equalities(a, b) &&
         std::memcmp(&a->opt, &b->opt, sizeof(mjOption)) == 0 && a->stat.meaninertia == b->stat.meaninertia;
}

} // namespace sreh
