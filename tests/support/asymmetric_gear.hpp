// Test helper: the outline of a gear with asymmetric teeth, built point by point (no generator of
// gearsim's makes one): each tooth's counter-clockwise side an involute of one base circle, its
// clockwise side of another, from a root circle above both to the tip circle, root and tip as
// arcs. Tooth 0 is centred on +x; at the reference radius r_ref every tooth is half a pitch thick.
#pragma once

#include <cmath>

#include "geometry/involute.hpp"
#include "geometry/outline.hpp"

namespace gearsim::test {

struct AsymmetricGear {
  int teeth = 20;
  double r_ref_m = 10e-3, r_root_m = 9.5e-3, r_tip_m = 11e-3;
  double rb_ccw_m = 10e-3 * std::cos(20 * M_PI / 180), rb_cw_m = 10e-3 * std::cos(25 * M_PI / 180);

  // Angle of a side from its tooth's centre line at radius r (≥ its base radius), rad.
  double side_angle(double rb, double r) const {
    return 0.5 * M_PI / teeth + involute(std::acos(rb / r_ref_m)) - involute(std::acos(rb / r));
  }

  Polygon2 outline(int flank_points = 40, int arc_points = 8) const {
    Polygon2 p;
    const double pitch = 2 * M_PI / teeth;
    auto at = [&](double r, double a) { p.points.emplace_back(r * std::cos(a), r * std::sin(a)); };
    for (int k = 0; k < teeth; ++k) {
      const double c = k * pitch;
      // Counter-clockwise round the gear: clockwise side up, tip land, counter-clockwise side down,
      // root land to the next tooth.
      for (int i = 0; i < flank_points; ++i) {
        const double r = r_root_m + (r_tip_m - r_root_m) * i / (flank_points - 1);
        at(r, c - side_angle(rb_cw_m, r));
      }
      const double tip_from = c - side_angle(rb_cw_m, r_tip_m), tip_to = c + side_angle(rb_ccw_m, r_tip_m);
      for (int i = 1; i < arc_points; ++i) at(r_tip_m, tip_from + (tip_to - tip_from) * i / arc_points);
      for (int i = flank_points - 1; i >= 0; --i) {
        const double r = r_root_m + (r_tip_m - r_root_m) * i / (flank_points - 1);
        at(r, c + side_angle(rb_ccw_m, r));
      }
      const double root_from = c + side_angle(rb_ccw_m, r_root_m), root_to = c + pitch - side_angle(rb_cw_m, r_root_m);
      for (int i = 1; i < arc_points; ++i) at(r_root_m, root_from + (root_to - root_from) * i / arc_points);
    }
    return p;
  }
};

}  // namespace gearsim::test
