#include "fe/iso6336_stiffness.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "core/errors.hpp"
#include "fe/constants.hpp"

namespace gearsim::fe {
namespace {

// Reject what ISO 6336-1 method B does not cover.
void validate(const IsoPairDef& d) {
  if (d.z1 < 5) throw InputError("ISO 6336 stiffness: z1 must be an external gear with >= 5 teeth, got " + std::to_string(d.z1));
  if (d.z2 == 0 || std::abs(d.z2) < 5) throw InputError("ISO 6336 stiffness: |z2| must be >= 5, got " + std::to_string(d.z2));
  if (!(d.pressure_angle_rad > 0.0 && d.pressure_angle_rad < 0.6))
    throw InputError("ISO 6336 stiffness: pressure_angle_rad must be in (0, 0.6)");
  if (!(std::abs(d.helix_angle_rad) < 0.8)) throw InputError("ISO 6336 stiffness: |helix_angle_rad| must be < 0.8");
  if (!(d.dedendum_over_module > 0.5 && d.dedendum_over_module < 2.0))
    throw InputError("ISO 6336 stiffness: dedendum_over_module must be in (0.5, 2)");
  if (!(d.contact_ratio >= 1.0 && d.contact_ratio < 3.0)) throw InputError("ISO 6336 stiffness: contact_ratio must be in [1, 3)");
}

}  // namespace

double iso_theoretical_single_stiffness(const IsoPairDef& d) {
  validate(d);
  // Virtual numbers of teeth z_n = z / cos³β; an internal gear counts as z_n2 = ∞ (ISO 6336-1).
  const double cb3 = std::pow(std::cos(d.helix_angle_rad), 3);
  const double zn1 = d.z1 / cb3;
  const double inv_zn2 = d.z2 < 0 ? 0.0 : cb3 / d.z2;
  // Flexibility q' in mm·µm/N, eq. (75).
  const double q = kIsoC1 + kIsoC2 / zn1 + kIsoC3 * inv_zn2 + kIsoC4 * d.x1 + kIsoC5 * d.x1 / zn1 + kIsoC6 * d.x2 +
                   kIsoC7 * d.x2 * inv_zn2 + kIsoC8 * d.x1 * d.x1 + kIsoC9 * d.x2 * d.x2;
  return kNPerMmUm_in_NPerM2 / q;
}

double iso_single_stiffness(const IsoPairDef& d) {
  // Basic rack factor C_B, eq. (77) for equal racks.
  const double alpha_deg = d.pressure_angle_rad * 180.0 / std::numbers::pi;
  const double cb = (1.0 + 0.5 * (1.2 - d.dedendum_over_module)) * (1.0 - 0.02 * (20.0 - alpha_deg));
  return iso_theoretical_single_stiffness(d) * kIsoCorrectionCM * kIsoBlankCR * cb * std::cos(d.helix_angle_rad);
}

double iso_mesh_stiffness(const IsoPairDef& d) { return iso_single_stiffness(d) * (0.75 * d.contact_ratio + 0.25); }

}  // namespace gearsim::fe
