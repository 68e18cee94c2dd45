// Test helpers: spur gear specs with the paper's proportions (m = 1 mm, α = 20°, standard rack),
// built in code so geometry tests need no file parser.
#pragma once

#include "geometry/gear_spec.hpp"

namespace gearsim::test {

inline GearSpec external_gear(int teeth, double bore_m = 0.008) {
  GearSpec s;
  s.name = "ext" + std::to_string(teeth);
  s.teeth = teeth;
  s.module_m = 1e-3;
  s.face_width_m = 0.010;
  s.bore_diameter_m = bore_m;
  return s;
}

inline GearSpec internal_gear(int teeth, double rim_m = 0.110) {
  GearSpec s;
  s.name = "int" + std::to_string(teeth);
  s.kind = GearKind::Internal;
  s.teeth = teeth;
  s.module_m = 1e-3;
  s.face_width_m = 0.010;
  s.rim_diameter_m = rim_m;
  return s;
}

}  // namespace gearsim::test
