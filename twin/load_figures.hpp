// What a load is, in the figures a machine builder sizes with (issue 28,
// `sreh-twin load show`): mass, inertia about the axis, centre of mass,
// the largest gravity torque, the ratio to the module's own inertia, and
// each part's share. From the compiled MuJoCo model, the same one the twin
// runs: each body's inertia about the flange axis by the parallel-axis
// theorem, so the parts add up to the mass matrix's figure.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "twin/specs.hpp"

namespace sreh {

struct PartFigures {
  std::string shape;          // "disk", "mesh", ... for parts; "load" for a one-shape load
  std::string name;           // the part's `name:`, or empty
  double mass_kg = 0;
  double inertia_kgm2 = 0;    // about the flange axis
  std::array<double, 3> com_m{}; // in the flange frame
};

struct LoadFigures {
  double mass_kg = 0;
  double inertia_kgm2 = 0;       // about the flange axis (MuJoCo's mass matrix)
  std::array<double, 3> com_m{}; // centre of mass in the flange frame (z up from the mounting face)
  double com_radius_m = 0;       // its distance from the axis
  double gravity_m_s2 = 9.81;    // the module model's gravity
  std::array<double, 3> face_world_m{}; // the mounting face's centre in the module model's world (pictures)
  std::vector<PartFigures> parts;
};

// Builds the load on the module (throws std::invalid_argument as build_model).
LoadFigures load_figures(const LoadSpec& load);

// The largest gravity torque about the axis over a turn of the flange:
// m g r sin(tilt) (A-TWIN-24), with r the centre of mass's distance from the axis.
double gravity_torque_max_Nm(const LoadFigures& f, double tilt_deg);

} // namespace sreh
