// The RMS torque of a single move's cycle as its plan predicts it (issue 37):
// the order and the window of the gentlest search (A-SIZE-10, A-SIZE-26).
// From the planned profile and the model card only, no simulation: the
// motor torque (referred to the output) the drive must give to follow the
// plan exactly, with the drive train as the twin models it (A-TWIN-4,
// A-TWIN-22, A-TWIN-46): the whole axis inertia times the acceleration,
// the rotor's Coulomb friction, its viscous drag, the gear's loss growing
// with the torque it transmits, and gravity on the load when the axis is
// not vertical; at rest between moves the gravity torque and the friction's
// breakaway the drive keeps pushing against. What it leaves out (the
// controller's tracking, the gear's spring and backlash, cogging, Stribeck
// near standstill, the 2 ms sampling of the trace) is what
// bench/gentle_proxy.py measures.
#pragma once
#include <vector>

#include "device_logic/planner.hpp"
#include "sizing/sizing.hpp"

namespace sreh::sizing {

// The gentlest search runs every set whose proxy is within this fraction
// of the best feasible set's proxy (A-SIZE-26: the measured spread of the
// simulated RMS over the proxy, with its margin).
inline constexpr double kGentleProxyWindow = 0.02;

class TorqueProxy {
 public:
  // The load's figures (for gravity) are built once here when the axis is
  // tilted; `load_gcm2` is the load's inertia (validate()).
  TorqueProxy(const SizingRequest& rq, double load_gcm2);

  // RMS over one back-and-forth cycle of `move` (planned from 0 to the
  // request's angle): out, `hold_s` at rest, back, `hold_s` at rest, N m.
  double cycle_rms_Nm(const Profile& move, double hold_s) const;

 private:
  // The torque the plan asks for at one instant of a move that started at
  // flange angle `start_rad` in direction `direction` (+1 / -1), N m.
  double torque_Nm(const KinematicState& along, double direction, double start_rad) const;
  double move_torque_sq_integral(const Profile& move, double direction, double start_rad) const;
  double gravity_Nm(double flange_rad) const;

  double axis_inertia_kgm2_ = 0;   // J_intern + load: what the motor accelerates
  double flange_inertia_kgm2_ = 0; // what the gear transmits to (axis minus rotor)
  double coulomb_Nm_ = 0;
  double breakaway_Nm_ = 0;        // Coulomb + Stribeck excess: what the rotor's friction holds at rest
  double viscous_Nms_per_rad_ = 0;
  double gear_loss_ = 0;           // 1 - gear efficiency
  double gravity_max_Nm_ = 0;      // m g r sin(tilt)
  double com_angle_rad_ = 0;       // the load's centre of mass around the axis at flange angle 0
};

// A set the gentlest search may run: its plan's travel and proxy.
struct PlannedSet {
  MotionSetting setting;
  double travel_s = 0;
  double rms_proxy_Nm = 0; // TorqueProxy::cycle_rms_Nm
};

// The grid points meeting the request's target, in the order the gentlest
// search runs them (lowest proxy first; search.cpp), for the bench and the
// test that measure the proxy's error.
std::vector<PlannedSet> gentlest_order(const SizingRequest& rq, double load_gcm2);

} // namespace sreh::sizing
