// Analytical potential-energy mesh stiffness of a standard spur gear pair (Yang & Lin 1987,
// Tian 2004, Chen & Shao 2011; fillet foundation of Sainsot et al. 2004): each tooth is a
// non-uniform cantilever clamped on the base circle, or on the root circle when that is larger
// (z > 41 at 20°, dedendum 1.25 m); a contact force along the line of action stores bending,
// shear and axial energy in both teeth, Hertzian energy at the contact and fillet-foundation
// energy in both gear bodies. The mesh stiffness is the sum over the tooth pairs in contact.
// External pairs and internal pairs (z2 < 0: a pinion/planet meshing with a ring) are covered.
// Not covered: profile shift (x = 0 only), tip relief, cracks, helical gears, ring rim bending
// (the ring's foundation uses Sainsot's external-body fit by analogy), load-dependent contact,
// tip and trochoid interference of internal pairs (only involute interference is rejected).
// Not a contact model: it yields numbers in SI (N/m; per face width N/m², 1 N/(mm·µm) = 1e9 N/m²).
#pragma once

#include <array>
#include <vector>

#include "fe/constants.hpp"

namespace gearsim::fe {

// Description of one spur gear pair for the potential-energy stiffness (mirrors IsoPairDef).
struct PotentialEnergyPairDef {
  int z1 = 20;  // pinion teeth (external), >= 5
  int z2 = 31;  // wheel teeth; negative for an internal gear (ring)
  double module_m = 1e-3;  // module m, in m
  double pressure_angle_rad = 0.3490658503988659;  // pressure angle α, normally 20°
  double face_width_m = 10e-3;  // face width b, in m
  double addendum_over_module = 1.0;  // h_a / m, normally 1.0
  double dedendum_over_module = 1.25;  // h_f / m, normally 1.25
  // Tip radius of the generating rack ρ / m, normally 0.38 (ISO 53 profile A); it sets the tooth
  // thickness at the root circle S_f of the fillet-foundation term.
  double rack_tip_radius_over_module = 0.38;
  double young_modulus_Pa = kYoungModulus_Pa;  // E, in Pa (both gears)
  double poisson_ratio = kPoissonRatio;  // ν, dimensionless, in [0, 0.5)
  // Sainsot's h_f = r_f / r_int of each body (root over bore radius), dimensionless.
  double root_over_bore1 = kPeDefaultRootOverBore;
  double root_over_bore2 = kPeDefaultRootOverBore;
  bool include_fillet_foundation = true;  // false: rigid gear bodies (Tian's model)
};

// Compliances of one tooth loaded at one contact point, in m/N (deflection along the line of
// action per unit normal force).
struct ToothCompliance {
  double bending_m_per_N = 0;  // 1/k_b
  double shear_m_per_N = 0;  // 1/k_s
  double axial_m_per_N = 0;  // 1/k_a
  double foundation_m_per_N = 0;  // 1/k_f (0 when the foundation is left out)
  double total_m_per_N() const { return bending_m_per_N + shear_m_per_N + axial_m_per_N + foundation_m_per_N; }
};

// One tooth pair at one contact point: the terms and the pair stiffness
// 1/k = 1/k_h + Σ_gears (1/k_b + 1/k_s + 1/k_a + 1/k_f).
struct PairCompliance {
  double pinion_contact_radius_m = 0;
  double wheel_contact_radius_m = 0;
  ToothCompliance pinion, wheel;
  double hertz_m_per_N = 0;  // 1/k_h
  double stiffness_N_per_m = 0;  // k
};

// The path of contact along the line of action, as the pinion's roll length (distance of the
// contact point from the pinion's base tangent point), in m.
struct ContactPath {
  double start_roll_m = 0;  // first contact (wheel tip, or ring tip)
  double end_roll_m = 0;  // last contact (pinion tip)
  double base_pitch_m = 0;  // p_b = π m cos α
  double contact_ratio = 0;  // ε_α = (end − start) / p_b, closed form from tip and base radii
  double pinion_base_radius_m = 0;
};

// Hertzian contact stiffness k_h = π E b / (4 (1 − ν²)) (Yang & Lin 1987; plane strain, equal
// materials, independent of the contact position), in N/m. Throws InputError.
double hertz_stiffness(const PotentialEnergyPairDef& def);
// Path of contact of the pair; throws InputError on bad input or a pair that interferes
// (contact reaching below a base circle).
ContactPath contact_path(const PotentialEnergyPairDef& def);
// All terms for one tooth pair with the contact at the given pinion radius (m), which must lie on
// the path of contact. Throws InputError.
PairCompliance single_pair_compliance(const PotentialEnergyPairDef& def, double pinion_contact_radius_m);
// Stiffness of one tooth pair (N/m) with the contact at the given pinion radius (m).
double single_pair_stiffness(const PotentialEnergyPairDef& def, double pinion_contact_radius_m);

// One sample of the mesh stiffness over a mesh period.
struct StiffnessSample {
  double roll_angle_rad = 0;  // pinion rotation since the leading pair entered contact
  double mesh_stiffness_N_per_m = 0;  // sum over the pairs in contact
  std::array<double, kPeMaxPairsInContact> pair_stiffness_N_per_m{};  // 0 for absent pairs
  std::array<double, kPeMaxPairsInContact> pinion_contact_radius_m{};  // 0 for absent pairs
  int pairs_in_contact = 0;
};

// Mesh stiffness over one mesh period (pinion rotation 2π/z1), samples_per_period ≥ 10
// equally spaced samples starting where a pair enters contact. Throws InputError.
std::vector<StiffnessSample> mesh_stiffness_curve(const PotentialEnergyPairDef& def, int samples_per_period);

// Statistics of a mesh stiffness curve.
struct StiffnessSummary {
  double mean_N_per_m = 0, min_N_per_m = 0, max_N_per_m = 0;  // mesh stiffness, in N/m
  double mean_per_width_N_per_m2 = 0;  // mean / b, in N/m² (1e9 N/m² = 1 N/(mm·µm))
  double contact_ratio = 0;  // mean number of pairs in contact over the period
  double single_pair_max_N_per_m = 0;  // stiffest single pair anywhere on the curve, in N/m
};
// Summary of mesh_stiffness_curve(def, samples_per_period).
StiffnessSummary summarize_mesh_stiffness(const PotentialEnergyPairDef& def, int samples_per_period);

}  // namespace gearsim::fe
