// ISO 6336-1:2019 method B tooth stiffness: single-tooth stiffness c' and mesh stiffness c_γα,
// the closed-form reference the finite-element pair stiffness is compared against.
// Not a contact model: it yields numbers, per unit face width, in SI (N/m per m = N/m²).
#pragma once

namespace gearsim::fe {

// Description of one gear pair for ISO 6336-1 stiffness.
struct IsoPairDef {
  int z1 = 20;  // pinion teeth (external)
  int z2 = 31;  // wheel teeth; negative for an internal gear (ring)
  double x1 = 0.0;  // pinion profile shift coefficient, in module units
  double x2 = 0.0;  // wheel profile shift coefficient, in module units
  double pressure_angle_rad = 0.3490658503988659;  // normal pressure angle α_n, normally 20°
  double helix_angle_rad = 0.0;  // β, 0 for spur gears
  double dedendum_over_module = 1.25;  // basic rack dedendum h_fP / m_n, normally 1.25
  double contact_ratio = 1.5;  // transverse contact ratio ε_α (for c_γα)
};

// Theoretical single-tooth stiffness c'_th (N/m², i.e. N/m per m face width); throws InputError.
double iso_theoretical_single_stiffness(const IsoPairDef& def);
// Single-tooth stiffness c' = c'_th · C_M · C_R · C_B · cos β (N/m²).
double iso_single_stiffness(const IsoPairDef& def);
// Mean mesh stiffness c_γα = c' · (0.75 ε_α + 0.25) (N/m²).
double iso_mesh_stiffness(const IsoPairDef& def);

}  // namespace gearsim::fe
