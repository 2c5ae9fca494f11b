#include "twin/supply.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sreh {
namespace {
// A numerical floor, not a property of the module: P / U has no meaning
// near 0 V, where the output stage is off anyway (A-TWIN-11).
constexpr double kMinBusForCurrent_V = 1.0;
} // namespace


Supply::Supply(const SupplySpec& spec, const SupplyConstants& constants)
    : spec_(spec), constants_(constants), bus_V_(spec.voltage_V) {
  if (!(spec.voltage_V >= 0) || !(spec.source_resistance_ohm >= 0) || !(spec.bus_capacitance_F >= 0)) {
    throw std::invalid_argument("supply: voltage_V, source_resistance_ohm and bus_capacitance_F must be >= 0");
  }
}

void Supply::set_source_voltage(double volts) {
  spec_.voltage_V = std::max(0.0, volts);
  if (spec_.source_resistance_ohm == 0.0) bus_V_ = spec_.voltage_V;
}

void Supply::step(double dt_s, double load_power_W) {
  const double us = spec_.voltage_V;
  const double r = spec_.source_resistance_ohm;
  const double c = spec_.bus_capacitance_F;
  if (r == 0.0) { // ideal source: it sources and sinks anything
    bus_V_ = us;
    load_A_ = load_power_W / std::max(bus_V_, kMinBusForCurrent_V);
    source_A_ = load_A_;
    return;
  }
  if (c == 0.0) {
    // Resistive source, no storage: U = Us - R P / U (the source may sink).
    // Beyond the maximum transferable power the bus collapses to Us / 2.
    const double disc = us * us - 4.0 * r * load_power_W;
    bus_V_ = disc > 0 ? (us + std::sqrt(disc)) / 2.0 : us / 2.0;
    load_A_ = load_power_W / std::max(bus_V_, kMinBusForCurrent_V);
    source_A_ = load_A_;
    return;
  }
  // Source through R and a diode (a power supply cannot sink current) into the
  // bus capacitor; the output stage draws P / U; the electronics bleed it.
  // Forward Euler with a stability guard: sub-steps below RC / 2.
  const double tau = r * c;
  const int n = std::max(1, static_cast<int>(std::ceil(2.0 * dt_s / tau)));
  const double h = dt_s / n;
  for (int i = 0; i < n; ++i) {
    const double u = std::max(bus_V_, kMinBusForCurrent_V);
    load_A_ = load_power_W / u;
    source_A_ = std::max(0.0, (us - bus_V_) / r);
    const double bleed_A = bus_V_ / constants_.bleed_resistance_ohm;
    bus_V_ += h * (source_A_ - load_A_ - bleed_A) / c;
    bus_V_ = std::max(bus_V_, 0.0);
  }
}

} // namespace sreh
