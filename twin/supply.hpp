// Motor supply (pins 2 and 5, manual 6.4 index 113): ideal by default; with a
// source resistance the bus sags under load, and with a bus capacitance
// braking energy charges it (no braking chopper: manual 7.2, error 114.4.2).
#pragma once
#include "twin/module_model.hpp"
#include "twin/specs.hpp"

namespace sreh {

class Supply {
 public:
  Supply(const SupplySpec& spec, const SupplyConstants& constants); // constants: model card

  // Source (power supply unit) voltage; the bus follows it.
  void set_source_voltage(double volts);
  double source_voltage_V() const { return spec_.voltage_V; }

  // Advances dt_s with the motor drawing `load_power_W` from the bus
  // (negative: regeneration).
  void step(double dt_s, double load_power_W);

  double bus_voltage_V() const { return bus_V_; }
  double load_current_A() const { return load_A_; }   // into the output stage
  double source_current_A() const { return source_A_; } // out of the power supply (>= 0 with C)

 private:
  SupplySpec spec_;
  SupplyConstants constants_;
  double bus_V_;
  double load_A_ = 0;
  double source_A_ = 0;
};

} // namespace sreh
