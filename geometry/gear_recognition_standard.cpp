// Gear recognition, the standard reading: which module (ISO 54, DIN 780 or a diametral pitch)
// and pressure angle a gear's fitted involutes are, with the reference thickness and profile
// shift that follow. Not the fits themselves (gear_recognition_flanks.cpp).
#include <array>
#include <cmath>

#include "geometry/gear_recognition_detail.hpp"

namespace gearsim::recognition_detail {
namespace {

// A standard (m, α) matches when m·cos α agrees with the measured base pitch / π to this
// fraction (14.5° and 15° differ by 0.23 %; a 2 µm error of r_b on a 5 mm base circle is 0.04 %).
constexpr double kStandardMatch = 1e-3;

// Modules of ISO 54 (series I and II) and DIN 780 fine modules, mm.
constexpr std::array kModules_mm = {0.05, 0.06, 0.07, 0.08, 0.09, 0.1,  0.11, 0.12, 0.14, 0.15, 0.16, 0.18, 0.2,  0.22, 0.25,  0.28, 0.3,
                                    0.35, 0.4,  0.45, 0.5,  0.55, 0.6,  0.65, 0.7,  0.75, 0.8,  0.85, 0.9,  0.95, 1.0,  1.125, 1.25, 1.375,
                                    1.5,  1.75, 2.0,  2.25, 2.5,  2.75, 3.0,  3.5,  4.0,  4.5,  5.0,  5.5,  6.0,  7.0,  8.0,   9.0,  10.0,
                                    11.0, 12.0, 14.0, 16.0, 18.0, 20.0, 22.0, 25.0, 28.0, 32.0, 36.0, 40.0, 45.0, 50.0};
// Diametral pitches, 1/in (module = 25.4 mm / P).
constexpr std::array kDiametralPitches = {1.0,  1.25, 1.5,  1.75, 2.0,  2.25, 2.5,  3.0,  4.0,  5.0,  6.0,  8.0,   10.0,  12.0, 14.0,
                                          16.0, 18.0, 20.0, 24.0, 32.0, 40.0, 48.0, 64.0, 72.0, 80.0, 96.0, 120.0, 128.0, 200.0};
constexpr std::array kPressureAngles_deg = {14.5, 15.0, 16.0, 17.5, 18.0, 20.0, 22.5, 25.0, 28.0, 30.0};
// Weight of a candidate's |profile shift| against its relative depth error when choosing (m, α):
// 0.2 makes a shift of 0.5 (about the largest in use) cost as much as a depth 10 % off 2.25 m.
constexpr double kShiftWeight = 0.2;

// Tooth thickness at the reference circle m·z/2 of a candidate module, from the two flank fits, m.
double reference_thickness(const RecognisedGear& g, double module_m) {
  const double sigma = g.internal ? -1.0 : 1.0, r = 0.5 * module_m * g.teeth;
  const double half_ccw = g.ccw.base_half_angle_rad - sigma * inv_at(g.ccw.base_radius_m, r);
  const double half_cw = g.cw.base_half_angle_rad - sigma * inv_at(g.cw.base_radius_m, r);
  return r * (half_ccw + half_cw);
}

// Profile shift coefficient of a candidate (m, α): the reference thickness beyond half the pitch,
// over 2·m·tan α (ISO 21771, external gears). For a ring the same formula on its tooth gives the
// shift's size; its sign convention varies, so only the size is used (to choose m and α).
double profile_shift(const RecognisedGear& g, double module_m, double pressure_angle_rad) {
  return (reference_thickness(g, module_m) / module_m - 0.5 * kPi) / (2 * std::tan(pressure_angle_rad));
}

}  // namespace

// Module and pressure angle from the base pitch, the depth and the tooth thickness (see
// RecognisedGear::standard). Every standard (m, α) with m·cos α on the base pitch is a valid
// reading of the same involutes (a change of α is a change of profile shift); the one chosen
// needs the least departure from a standard gear: its depth nearest 2.25 m and its profile shift
// nearest 0, weighted kShiftWeight per unit of shift. E.g. a 60-tooth ring of m 1 mm, 25° with a
// 2.05 m stub depth also reads as m 0.95 mm, 17.5° with depth 2.16 m — but a shift of 1.9.
void module_and_pressure_angle(RecognisedGear& g) {
  const double mcos = g.base_pitch_m / kPi, m_depth = std::abs(g.root_radius_m - g.tip_radius_m) / kRackDepth;
  double best_score = 1e300;
  auto consider = [&](double m) {
    if (m < 0.75 * m_depth || m > 1.33 * m_depth) return;
    for (double a_deg : kPressureAngles_deg) {
      const double a = a_deg * kPi / 180;
      if (std::abs(m * std::cos(a) - mcos) > kStandardMatch * mcos) continue;
      const double score = std::abs(m / m_depth - 1) + kShiftWeight * std::abs(profile_shift(g, m, a));
      if (score < best_score) best_score = score, g.module_m = m, g.pressure_angle_rad = a, g.standard = true;
    }
  };
  for (double m_mm : kModules_mm) consider(m_mm * 1e-3);
  for (double p : kDiametralPitches) consider(25.4e-3 / p);
  if (!g.standard) {
    g.module_m = m_depth;
    g.pressure_angle_rad = mcos < m_depth ? std::acos(mcos / m_depth) : 0.0;
  }
  g.reference_radius_m = 0.5 * g.module_m * g.teeth;
  g.reference_thickness_m = reference_thickness(g, g.module_m);
  if (!g.internal && g.pressure_angle_rad > 0) g.profile_shift = profile_shift(g, g.module_m, g.pressure_angle_rad);
}

}  // namespace gearsim::recognition_detail
