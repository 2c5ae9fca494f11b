// TorqueProxy (rms_proxy.hpp): the plan's torque, integrated exactly.
#include "sizing/rms_proxy.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "device_logic/units.hpp"
#include "twin/load_figures.hpp"

namespace sreh::sizing {

TorqueProxy::TorqueProxy(const SizingRequest& rq, double load_gcm2) {
  const MechanicsConstants& m = rq.world.module.mechanics;
  axis_inertia_kgm2_ = kInternalInertia_kgm2 + gcm2_to_kgm2(load_gcm2);
  flange_inertia_kgm2_ = std::max(0.0, axis_inertia_kgm2_ - m.rotor_inertia_kgm2);
  coulomb_Nm_ = m.coulomb_friction_Nm;
  breakaway_Nm_ = m.coulomb_friction_Nm + m.stribeck_excess_Nm;
  viscous_Nms_per_rad_ = m.viscous_friction_Nms_per_rad;
  gear_loss_ = 1.0 - m.gear_efficiency;
  if (std::sin(rq.world.mounting_tilt_deg * std::numbers::pi / 180.0) != 0) {
    try {
      const LoadFigures f = load_figures(rq.world.load);
      gravity_max_Nm_ = gravity_torque_max_Nm(f, rq.world.mounting_tilt_deg);
      com_angle_rad_ = std::atan2(f.com_m[1], f.com_m[0]);
    } catch (const std::invalid_argument&) {
      gravity_max_Nm_ = 0; // a load the twin rejects fails every run anyway
    }
  }
}

// A-TWIN-24: the axis tilted, the load's centre of mass at angle a around
// the axis (a = 0 along +x: the largest torque); the drive holds it with
// -m g r sin(tilt) cos(a), the sign as the twin's trace shows it (the rated
// arm at rest at 0 deg: -0.11 N m, A-SIZE-26).
double TorqueProxy::gravity_Nm(double flange_rad) const {
  return -gravity_max_Nm_ * std::cos(flange_rad + com_angle_rad_);
}

// The rotor's dry friction grows by (1 - efficiency) x the torque the gear
// transmits (A-TWIN-46); it and the drag oppose the motion.
double TorqueProxy::torque_Nm(const KinematicState& along, double direction, double start_rad) const {
  const double acc = direction * along.acc_rad_s2;
  const double vel = direction * along.vel_rad_s;
  const double gravity = gravity_Nm(start_rad + direction * along.pos_rad);
  const double transmitted = flange_inertia_kgm2_ * acc + gravity;
  const double dry = vel > 0 ? 1.0 : (vel < 0 ? -1.0 : 0.0);
  return axis_inertia_kgm2_ * acc + gravity + dry * (coulomb_Nm_ + gear_loss_ * std::abs(transmitted)) +
         viscous_Nms_per_rad_ * vel;
}

// Integral of the squared torque over the move: three-point Gauss-Legendre
// per constant-jerk phase, exact without gravity (acceleration linear,
// speed quadratic in a phase, so the torque squared is a quartic; the
// acceleration keeps its sign within a phase); with gravity each phase is
// cut in eight.
double TorqueProxy::move_torque_sq_integral(const Profile& move, double direction, double start_rad) const {
  static constexpr std::array<double, 3> kNode = {-0.7745966692414834, 0.0, 0.7745966692414834};
  static constexpr std::array<double, 3> kWeight = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  const int pieces = gravity_max_Nm_ != 0 ? 8 : 1;
  double sum = 0, t0 = 0;
  for (double d : move.phase_durations_s()) {
    if (d <= 0) continue;
    const double h = d / pieces;
    for (int p = 0; p < pieces; ++p) {
      const double mid = t0 + (p + 0.5) * h;
      for (std::size_t k = 0; k < kNode.size(); ++k) {
        const double tau = torque_Nm(move.at(mid + 0.5 * h * kNode[k]), direction, start_rad);
        sum += 0.5 * h * kWeight[k] * tau * tau;
      }
    }
    t0 += d;
  }
  return sum;
}

double TorqueProxy::cycle_rms_Nm(const Profile& move, double hold_s) const {
  const double end_rad = move.end_position_rad();
  const double out = move_torque_sq_integral(move, 1.0, 0.0);
  const double back = gravity_max_Nm_ != 0 ? move_torque_sq_integral(move, -1.0, end_rad) : out;
  // At rest the drive keeps pushing the way it moved, the rotor's dry
  // friction holding it (up to the breakaway) as it held the move's last
  // instant: the hold torque is the gravity torque plus the breakaway in
  // the direction of the move just made (measured in the twin, A-SIZE-26).
  const double g_end = gravity_Nm(end_rad) + breakaway_Nm_, g_start = gravity_Nm(0.0) - breakaway_Nm_;
  const double total_s = 2.0 * (move.duration_s() + hold_s);
  return total_s > 0 ? std::sqrt((out + back + hold_s * (g_end * g_end + g_start * g_start)) / total_s) : 0.0;
}

} // namespace sreh::sizing
