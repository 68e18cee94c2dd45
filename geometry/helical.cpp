#include "geometry/helical.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/constants.hpp"

namespace gearsim {

void set_transverse(GearSpec& s, const NormalValues& n) {
  const double c = std::cos(n.helix_angle_rad);
  s.helix_angle_rad = n.helix_angle_rad;
  s.module_m = n.module_m / c;
  // A spur gear's angle as given, bit for bit (atan(tan α) may differ from α in the last bit).
  s.pressure_angle_rad = n.helix_angle_rad == 0 ? n.pressure_angle_rad : std::atan(std::tan(n.pressure_angle_rad) / c);
  s.addendum_coeff = n.addendum_coeff * c;
  s.dedendum_coeff = n.dedendum_coeff * c;
  s.root_fillet_coeff = n.root_fillet_coeff * c;
  s.profile_shift = n.profile_shift * c;
}

double normal_module_m(const GearSpec& s) { return s.module_m * std::cos(s.helix_angle_rad); }

double normal_pressure_angle_rad(const GearSpec& s) { return std::atan(std::tan(s.pressure_angle_rad) * std::cos(s.helix_angle_rad)); }

double base_helix_angle_rad(const GearSpec& s) { return std::atan(std::tan(s.helix_angle_rad) * std::cos(s.pressure_angle_rad)); }

double normal_to_transverse_m(const GearSpec& s, double normal_length_m) { return normal_length_m / std::cos(base_helix_angle_rad(s)); }

double twist_rad_per_m(const GearSpec& s) { return std::tan(s.helix_angle_rad) / (0.5 * s.module_m * s.teeth); }

double overlap_ratio(const GearSpec& a, const GearSpec& b) {
  const double width = std::min(a.face_width_m, b.face_width_m);
  return width * std::abs(std::sin(a.helix_angle_rad)) / (constants::kPi * normal_module_m(a));
}

}  // namespace gearsim
