#include "geometry/gear_recognition.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include "geometry/gear_recognition_detail.hpp"

namespace gearsim {
namespace {

// Base radii of the two flank sides further apart than this fraction make an asymmetric tooth:
// 1e-3 is 10 µm on a 10 mm base circle, beyond any fit of a symmetric one (the corpus: ≤ 1.2 µm)
// and as much as kStandardMatch allows between (m, α) readings.
constexpr double kAsymmetry = 1e-3;

}  // namespace

Result<RecognisedGear> recognise_gear(const Outline2& outline) {
  using namespace recognition_detail;
  // The toothed loop: the one with the strongest tooth wave among those that have teeth.
  LoopTeeth best;
  int best_loop = -2;
  std::ostringstream why;
  for (int l = -1; l < static_cast<int>(outline.holes.size()); ++l) {
    LoopTeeth lt = loop_teeth(l < 0 ? outline.outer : outline.holes[static_cast<std::size_t>(l)], l < 0);
    if (lt.teeth > 0 && lt.amplitude_m > best.amplitude_m)
      best = std::move(lt), best_loop = l;
    else if (lt.teeth == 0)
      why << (why.tellp() > 0 ? "; " : "") << (l < 0 ? "outer loop" : "hole " + std::to_string(l)) << ": " << lt.why;
  }
  if (best_loop == -2) return Refusal{"no loop of the outline has teeth (" + why.str() + ")"};
  RecognisedGear g;
  g.teeth = best.teeth;
  g.internal = best_loop >= 0;
  g.loop = best_loop;
  const Polygon2& loop = best_loop < 0 ? outline.outer : outline.holes[static_cast<std::size_t>(best_loop)];
  std::vector<std::pair<double, double>> teeth = tooth_crossings(best, g.internal);
  // The axis from the teeth themselves, then the envelope and crossings about it.
  for (int pass = 0; pass < 2 && !teeth.empty(); ++pass) {
    const Eigen::Vector2d axis = refined_axis(loop, best);
    if ((axis - best.centre).norm() <= 1e-12 * best.r_max) break;
    std::vector<double> env = radial_envelope(loop, axis, best_loop < 0);
    if (env.empty()) break;
    best.centre = axis;
    best.env = std::move(env);
    const auto [lo, hi] = std::minmax_element(best.env.begin(), best.env.end());
    best.r_min = *lo, best.r_max = *hi;
    best.residual_m = symmetry_residual(best.env, best.teeth);
    teeth = tooth_crossings(best, g.internal);
  }
  if (teeth.empty()) {
    std::ostringstream m;
    m << "the toothed loop repeats " << g.teeth << " times but its mid-depth circle (r = " << 0.5 * (best.r_min + best.r_max) * 1e3
      << " mm) does not cross it twice per tooth";
    return Refusal{m.str()};
  }
  g.axis_m = best.centre;
  g.tip_radius_m = g.internal ? best.r_min : best.r_max;
  g.root_radius_m = g.internal ? best.r_max : best.r_min;
  g.symmetry_residual_m = best.residual_m;
  g.tooth0_angle_rad = tooth0_angle(teeth);
  const std::array<FlankPoints, 2> sides = flank_points(loop, g);
  g.ccw = fit_flank(sides[0], g);
  g.cw = fit_flank(sides[1], g);
  // Both sides on involutes of one base circle, or an asymmetric tooth (each side's fit stands).
  g.asymmetric = g.ccw.involute && g.cw.involute &&
                 std::abs(g.ccw.base_radius_m - g.cw.base_radius_m) > kAsymmetry * std::max(g.ccw.base_radius_m, g.cw.base_radius_m);
  g.involute = g.ccw.involute && g.cw.involute && !g.asymmetric;
  if (g.involute) {
    g.base_radius_m = (g.ccw.base_radius_m * g.ccw.points + g.cw.base_radius_m * g.cw.points) / (g.ccw.points + g.cw.points);
    g.base_pitch_m = 2 * kPi * g.base_radius_m / g.teeth;
    module_and_pressure_angle(g);
  } else {
    g.module_m = std::abs(g.root_radius_m - g.tip_radius_m) / kRackDepth;  // a size, for plausibility
  }
  return g;
}

Outline2 recentred(const Outline2& outline, const Eigen::Vector2d& axis_m) {
  Outline2 o = outline;
  for (Eigen::Vector2d& v : o.outer.points) v -= axis_m;
  for (Polygon2& h : o.holes)
    for (Eigen::Vector2d& v : h.points) v -= axis_m;
  return o;
}

}  // namespace gearsim
