// A lean model for twins that are never drawn (issue 31, A-TWIN-42): the
// module's geoms that only draw (housing, flange disc, marks, table, the
// setpoint ghost) left out, and (issue 37) the two bodies that carry no
// dynamics: the housing and the set-point ghost. Every MuJoCo step computes every geom's pose
// (mj_kinematics), ~12 % of a step for this model's 13 geoms, although
// without contacts (no hard stops) no geom takes part in the dynamics: the
// moving bodies carry explicit inertials. same_dynamics() proves that for
// each built model (load_builder.cpp compiles both once per world and keeps
// the full one if they differ), so the lean model steps bit for bit alike.
// Body ids differ between the two (the housing comes first): the moving
// subtree is compared, body for body in order.
#pragma once
#include <string>

#include <mujoco/mujoco.h>

namespace sreh {

// The MJCF text without the module's drawing geoms (by name, as in
// models/sreh50.xml), its lights and cameras, the body "setpoint_ghost"
// and the body "housing"; "led_band" (Plant::set_led_rgba) moves onto the
// world body, the loads stay.
std::string without_drawing_geoms(const std::string& xml);

// True when both models have contacts off, no tendons or sensors, and the
// same moving subtree (the bodies welded to a body with dofs: the same
// parents, placements and inertials, body for body), the same joints, dofs,
// joint actuators, joint equalities and options: everything mj_step reads
// that reaches a dof. Bodies welded to the world and mocap bodies may
// differ (their poses are computed, but no force of theirs reaches a dof).
bool same_dynamics(const mjModel* a, const mjModel* b);

} // namespace sreh
