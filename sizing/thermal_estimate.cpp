#include "sizing/thermal_estimate.hpp"

#include "sizing/sizing.hpp"
#include "device_logic/motor_model.hpp"
#include "twin/thermal.hpp"

namespace sreh::sizing {

ThermalEstimate estimate_thermal(double mean_loss_W, double ambient_C, const ThermalConstants& constants) {
  Thermal thermal(ThermalSpec{ambient_C, 1.0}, constants);
  ThermalEstimate e;
  e.steady_C = thermal.steady_winding_C(mean_loss_W);
  if (e.steady_C < kTemperatureWarning_C) return e;
  // Backward Euler (stable for any step): 0.5 s steps against the card's
  // time constants (36 s winding, 30 min housing); the steady state lies
  // above the warning, so the loop ends (bounded at 10 days anyway). It
  // goes on to the 75 degC trip (manual 7.2 114.3) when the steady state
  // reaches it.
  constexpr double kStep_s = 0.5;
  constexpr int kMaxSteps = 10 * 24 * 3600 * 2;
  const double last_C = e.steady_C >= kTemperatureTrip_C ? kTemperatureTrip_C : kTemperatureWarning_C;
  for (int i = 1; i <= kMaxSteps; ++i) {
    thermal.step(kStep_s, mean_loss_W);
    if (!e.time_to_warning_s && thermal.sensor_C() >= kTemperatureWarning_C) e.time_to_warning_s = i * kStep_s;
    if (!e.time_to_trip_s && thermal.sensor_C() >= kTemperatureTrip_C) e.time_to_trip_s = i * kStep_s;
    if (thermal.sensor_C() >= last_C) break;
  }
  return e;
}

std::vector<TemperaturePoint> temperature_curve(double mean_loss_W, double ambient_C, double duration_s,
                                                double step_s, const ThermalConstants& constants) {
  Thermal thermal(ThermalSpec{ambient_C, 1.0}, constants);
  std::vector<TemperaturePoint> out{{0.0, thermal.sensor_C()}};
  const int n = static_cast<int>(duration_s / step_s);
  for (int i = 1; i <= n; ++i) {
    thermal.step(step_s, mean_loss_W);
    out.push_back({i * step_s, thermal.sensor_C()});
  }
  return out;
}

} // namespace sreh::sizing

namespace sreh::sizing {

// A-SIZE-14: the continuous torque is the standstill torque whose copper
// loss holds the module's steady temperature at the 70 degC warning minus
// the required margin, at this ambient (the twin's own thermal model): what
// the pro tools call the rated/continuous torque, derated for ambient. It
// is at most the stage's peak torque (its current limit): with the
// issue-35 card's 3 + 6 K/W the motor could hold 0.89 N m at 25 degC,
// more than the stage gives.
double continuous_torque_Nm(double ambient_C, double thermal_margin_K, const ModuleModel& module) {
  const MotorModel& motor = module.drive.motor;
  const Thermal thermal(ThermalSpec{ambient_C, 1.0}, module.thermal);
  const double limit_C = kTemperatureWarning_C - thermal_margin_K;
  if (thermal.steady_winding_C(0.0) >= limit_C) return 0.0;
  const double peak_Nm = motor.peak_torque_Nm();
  if (thermal.steady_winding_C(motor.copper_loss_W(peak_Nm)) < limit_C) return peak_Nm;
  double lo = 0.0, hi = peak_Nm;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (thermal.steady_winding_C(motor.copper_loss_W(mid)) < limit_C ? lo : hi) = mid;
  }
  return lo;
}

} // namespace sreh::sizing
