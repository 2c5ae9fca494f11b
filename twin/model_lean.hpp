// A lean model for twins that are never drawn (issue 31, A-TWIN-42).
// Without contacts (no hard stops) no geom takes part in the dynamics, yet
// every MuJoCo step computes every body's and geom's pose (mj_kinematics):
// the lean model has no geoms at all (the module's drawing geoms left out,
// the moving bodies' geoms replaced by the inertials MuJoCo derived from
// them, issue 37) and no bodies without dynamics (the housing, welded to
// the world, and the set-point ghost, a mocap body). same_dynamics() proves
// for each built model that it steps bit for bit as the full one
// (load_builder.cpp compiles both once per world and keeps the full one if
// they differ). Body ids differ between the two (the housing comes first):
// the moving subtree is compared, body for body in order.
#pragma once
#include <string>

#include <mujoco/mujoco.h>

namespace sreh {

// The MJCF text of a twin never drawn, from `xml` and `compiled`, the model
// compiled from that very text: without the module's drawing geoms (by
// name, as in models/sreh50.xml), its lights and cameras, the bodies
// "housing" (with "led_band") and "setpoint_ghost"; every moving body with
// mass gets the inertial MuJoCo derived for it in `compiled` in place of
// its geoms (issue 37). The loads' bodies and sites stay.
std::string lean_xml(const std::string& xml, const mjModel* compiled);

// True when both models have contacts off, no tendons or sensors, and the
// same moving subtree (the bodies welded to a body with dofs: the same
// parents, placements and inertials, body for body), the same joints, dofs,
// joint actuators, joint equalities and options: everything mj_step reads
// that reaches a dof. Bodies welded to the world and mocap bodies may
// differ (their poses are computed, but no force of theirs reaches a dof).
bool same_dynamics(const mjModel* a, const mjModel* b);

} // namespace sreh
