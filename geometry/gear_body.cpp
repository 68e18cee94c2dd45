#include "geometry/gear_body.hpp"

#include "geometry/extrude.hpp"

namespace gearsim {

ToothLayout tooth_layout(const GearSpec& spec) { return {spec.teeth, spec.tooth0_angle_rad}; }

GearBody make_gear_body(const GearSpec& spec, double density_kg_m3) {
  GearBody b;
  b.spec = spec;
  b.outline = make_gear_outline(spec);
  const double half = 0.5 * spec.face_width_m;
  b.mesh = extrude(b.outline.outline, -half, half);
  DecompositionOptions options;
  options.tooth_layout = tooth_layout(spec);
  b.decomposition = decompose(b.outline.outline, options);
  b.pieces = extrude_pieces(b.decomposition, PrismFrame{}, -half, half);
  b.mass = mass_properties(b.mesh, density_kg_m3);
  return b;
}

}  // namespace gearsim
