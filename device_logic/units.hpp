// Every unit conversion in one place (docs/style.md 6). SI inside; units in names
// at every boundary.
#pragma once
#include <cstdint>
#include <numbers>

namespace sreh {

inline constexpr double kPi = std::numbers::pi;

// Position resolution (architecture.md "Units and encodings").
inline constexpr int64_t kWireCountsPerRev = int64_t{1} << 16;     // manual 2.5
inline constexpr int64_t kInternalCountsPerRev = int64_t{1} << 19; // manual 6.2, 64.5
inline constexpr int64_t kInternalPerWireCount = kInternalCountsPerRev / kWireCountsPerRev;

// Motor figures given by the manual (3.5.4).
inline constexpr double kMotorTorque_Nm = 0.485;
inline constexpr double kInternalInertia_kgm2 = 0.115e-3;
inline constexpr double kJerkRampTime_s = 0.010; // manual 3.5.5: jerk 100% reaches alpha100% in 10 ms

constexpr double deg_to_rad(double deg) { return deg * (kPi / 180.0); }
constexpr double rad_to_deg(double rad) { return rad * (180.0 / kPi); }
constexpr double gcm2_to_kgm2(double gcm2) { return gcm2 * 1e-7; }
constexpr double kgm2_to_gcm2(double kgm2) { return kgm2 * 1e7; }

constexpr double internal_counts_to_rad(int64_t counts) {
  return static_cast<double>(counts) * (2.0 * kPi / static_cast<double>(kInternalCountsPerRev));
}
constexpr double internal_counts_to_deg(int64_t counts) {
  return static_cast<double>(counts) * (360.0 / static_cast<double>(kInternalCountsPerRev));
}
constexpr double wire_counts_to_deg(int64_t counts) {
  return static_cast<double>(counts) * (360.0 / static_cast<double>(kWireCountsPerRev));
}
// Rounds to the nearest count (ties away from zero), no <cmath> needed in constexpr.
constexpr int64_t round_to_int64(double x) {
  return x >= 0 ? static_cast<int64_t>(x + 0.5) : -static_cast<int64_t>(-x + 0.5);
}
constexpr int64_t deg_to_wire_counts(double deg) {
  return round_to_int64(deg * (static_cast<double>(kWireCountsPerRev) / 360.0));
}
constexpr int64_t deg_to_internal_counts(double deg) {
  return round_to_int64(deg * (static_cast<double>(kInternalCountsPerRev) / 360.0));
}
constexpr int64_t rad_to_internal_counts(double rad) {
  return round_to_int64(rad * (static_cast<double>(kInternalCountsPerRev) / (2.0 * kPi)));
}

// Durations in integer nanoseconds, so clocks never accumulate float error
// (docs/style.md 8). Non-finite or negative durations count as 0.
inline int64_t seconds_to_ns(double s) { return s > 0.0 && s < 9e9 ? static_cast<int64_t>(s * 1e9 + 0.5) : 0; }
// Back to seconds for a step length or a sample time: one correctly rounded
// division (100'000 ns is exactly the double 1e-4), never a running sum.
constexpr double ns_to_seconds(int64_t ns) { return static_cast<double>(ns) / 1e9; }

// alpha100% = M / (J_intern + J_load), manual 3.5.4.
constexpr double alpha100_rad_s2(double load_gcm2) {
  return kMotorTorque_Nm / (kInternalInertia_kgm2 + gcm2_to_kgm2(load_gcm2));
}

} // namespace sreh
