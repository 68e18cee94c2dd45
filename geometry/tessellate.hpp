// Adaptive tessellation of plane curves with a bound on the chordal deviation (the largest
// distance between the curve and the polyline that replaces it). Not a spline library.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <vector>

namespace gearsim {

using Curve2 = std::function<Eigen::Vector2d(double)>;

// Appends points of curve(t) for t in [t0, t1) to `out` (t1's point is left to the next piece, so
// consecutive pieces concatenate without duplicates). Each chord is split until the curve points
// at ¼, ½ and ¾ of its parameter span lie within max_deviation_m of it; for the smooth, convex-
// per-span curves of a gear (involutes, trochoids, arcs) that bounds the deviation of the chord.
void tessellate_curve(const Curve2& curve, double t0, double t1, double max_deviation_m, std::vector<Eigen::Vector2d>& out);

// Appends the arc of the circle (centre, radius) from angle a0 to a1 (either direction), a1's
// point excluded, with the fewest equal segments whose sagitta is ≤ max_deviation_m.
void tessellate_arc(const Eigen::Vector2d& centre, double radius_m, double a0_rad, double a1_rad, double max_deviation_m,
                    std::vector<Eigen::Vector2d>& out);

// Number of equal segments an arc of this radius and span needs for the sagitta bound.
int arc_segments(double radius_m, double span_rad, double max_deviation_m);

// Distance from p to segment ab, m.
double distance_to_segment(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b);

}  // namespace gearsim
