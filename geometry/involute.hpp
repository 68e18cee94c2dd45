// Involute function and its inverse: the arithmetic every spur-gear formula is built on.
// Angles in rad, lengths in m. Not a gear: see gear_dimensions.hpp and gear_profile.hpp.
#pragma once

#include <cmath>

namespace gearsim {

// inv(α) = tan α − α.
inline double involute(double alpha_rad) { return std::tan(alpha_rad) - alpha_rad; }

// The α in [0, π/2) with inv(α) = value (value ≥ 0), by Newton's method to machine precision.
double inverse_involute(double value);

// Pressure angle of the involute of base radius rb at radius r ≥ rb.
inline double pressure_angle_at(double base_radius_m, double radius_m) { return std::acos(base_radius_m / radius_m); }

// Roll length (distance from the base-circle tangent point) of the involute point at radius r.
inline double roll_length_at(double base_radius_m, double radius_m) {
  return std::sqrt(radius_m * radius_m - base_radius_m * base_radius_m);
}

}  // namespace gearsim
