#include "geometry/gear_body.hpp"

#include <cmath>

#include "geometry/extrude.hpp"
#include "geometry/helical.hpp"

namespace gearsim {

ToothLayout tooth_layout(const GearSpec& spec) { return {spec.teeth, spec.tooth0_angle_rad}; }

GearBody make_gear_body(const GearSpec& spec, double density_kg_m3) {
  GearBody b;
  b.spec = spec;
  b.outline = make_gear_outline(spec);
  const double half = 0.5 * spec.face_width_m;
  // A helical gear's section turns along the axis: layers fine enough that the straight edges
  // between them leave the tip's helix by at most the chordal deviation (r·Δφ²/8 ≤ δ).
  b.mesh = spec.helix_angle_rad == 0 ? extrude(b.outline.outline, -half, half)
                                     : extrude_twisted(b.outline.outline, -half, half, twist_rad_per_m(spec),
                                                       std::sqrt(8 * spec.chordal_deviation_m / b.outline.dims.tip_radius_m));
  DecompositionOptions options;
  options.tooth_layout = tooth_layout(spec);
  b.decomposition = decompose(b.outline.outline, options);
  b.pieces = extrude_pieces(b.decomposition, PrismFrame{}, -half, half);
  b.mass = mass_properties(b.mesh, density_kg_m3);
  return b;
}

}  // namespace gearsim
