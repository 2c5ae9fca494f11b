// A lean model for twins that are never drawn (issue 31, A-TWIN-42): the
// module's geoms that only draw (housing, flange disc, marks, table, the
// setpoint ghost) left out. Every MuJoCo step computes every geom's pose
// (mj_kinematics), ~12 % of a step for this model's 13 geoms, although
// without contacts (no hard stops) no geom takes part in the dynamics: the
// moving bodies carry explicit inertials. same_dynamics() proves that for
// each built model (load_builder.cpp compiles both once per world and keeps
// the full one if they differ), so the lean model steps bit for bit alike.
#pragma once
#include <string>

#include <mujoco/mujoco.h>

namespace sreh {

// The MJCF text without the module's drawing geoms (by name, as in
// models/sreh50.xml), its lights and cameras; "led_band"
// (Plant::set_led_rgba) and the loads stay.
std::string without_drawing_geoms(const std::string& xml);

// True when both models have the same kinematic tree, the same inertials on
// every moving body, the same joints, dofs, actuators, equalities and
// options (everything mj_step reads besides geoms, with contacts off).
bool same_dynamics(const mjModel* a, const mjModel* b);

} // namespace sreh
