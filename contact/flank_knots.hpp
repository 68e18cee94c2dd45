// Flank knots: the vertices of a toothed outline loop that lie on each tooth's two flanks, as
// polar knots θ(r) about the gear axis (θ relative to the tooth's centre line, r ascending), and
// the cubic through them sampled on a radial grid. The step between a CAD mesh's outline and a
// FlankTable: it decides which vertices belong to a flank (not to a tip land, a root arc or noise)
// and interpolates them without overshoot where the flank has a corner or a straight piece.
// Not a table and not a probe: see flank_table.hpp.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "geometry/convex_decomposition.hpp"
#include "geometry/outline.hpp"

namespace gearsim::contact {

struct FlankKnots {
  std::vector<double> r_m;  // ascending, m
  std::vector<double> theta_rad;  // flank angle from the tooth's centre line at each r_m
};

// Knots of every flank of a loop: [tooth * 2 + side], side 0 the Ccw flank, 1 the Cw flank.
// A flank is the longest run of vertices along the loop, within one tooth's sector, whose
// radius grows steadily: each step rises in r by more than sin(kMinFlankSlope) of its length
// (so a flat tip land or a root arc, whatever its noise, ends a flank), and vertices closer than
// `merge_m` (m) to the last knot are passed over as too close to tell apart (CAD duplicates,
// coordinate noise). Throws InputError when a tooth has no flank of at least 4 knots.
std::vector<FlankKnots> flank_knots(const Polygon2& loop, const ToothLayout& layout, bool internal, double merge_m);

// The resolution of the knots, m: the median distance of each interior knot from the cubic
// through its four neighbours. Tiny on a generated outline; on a CAD mesh the larger of its
// facets' coarseness (µm at 5 facets per involute) and its coordinate noise.
double knot_resolution_m(const std::vector<FlankKnots>& flanks);

// θ at `samples` radii r0 + i·dr into out[i] (NaN outside the knots' range): per knot interval
// the cubic through four knots around it (Lagrange: the interval's two and one either side, or,
// where a stencil shifted by one knot has a third divided difference at least 4 times smaller,
// that one — next to the knot where an involute meets its fillet the centred cubic would reach
// into the fillet's curvature), or, where that cubic leaves the range of its interval's two
// knots (a corner, a straight radial piece next to an involute) or bows off its interval's chord
// by more than twice the sagitta of the circles through neighbouring knots plus the larger of
// 0.5 µm and `resolution_m` (knots so far apart that the cubic reaches for a neighbour's
// curvature: a flank of one or two chords), the shape-preserving Hermite cubic of Fritsch and
// Carlson (PCHIP) instead.
void sample_flank(const FlankKnots& k, double r0, double dr, int samples, double* out, double resolution_m = 0);

// How far sampled flank values stray from the polyline of their knots, beyond the sagitta a
// smooth curve through those knots has (from the circles through neighbouring knots), m.
struct FlankDeparture {
  double departure_m = 0;
  double r_m = 0;  // where it is largest
};
FlankDeparture flank_departure(const FlankKnots& k, double r0, double dr, int samples, const double* values);

}  // namespace gearsim::contact
