#include "contact/flank_knots.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "core/errors.hpp"
#include "geometry/constants.hpp"

namespace gearsim::contact {
namespace {

using gearsim::constants::kNaN;
using gearsim::constants::kPi;

// A step along a flank rises in radius by more than this share of its length: sin 1°. A tip land
// or root arc is flat (its noise, even 1 µm over 0.1 mm, stays below 0.01); an involute's chords
// rise at cos α_a ≥ 0.5 and a generated fillet's last chord at ~0.05.
constexpr double kMinFlankSlope = 0.0175;

// Consecutive knots rise by at least this much in radius, m: rounding of an arc's vertices
// (~1e-9 m at gear scale) must not pass for a flank.
constexpr double kMinKnotRise_m = 1e-8;

// A Lagrange value may leave its interval's knot range by this much before the interval takes
// the shape-preserving cubic, rad: rounding only (1e-14 m at 10 mm).
constexpr double kOvershoot_rad = 1e-12;

// A shifted stencil replaces the centred one where its third divided difference is this many
// times smaller (stencil()). On the paper's flanks the ratio is 0.7–2.0 along the involutes,
// 6.5–663 at their junctions with the fillets (docs/tooth-contact.md, "The cubic beside a
// fillet"): between the two.
constexpr double kStencilRatio = 4;

// A Lagrange cubic may bow off its interval's chord by twice the sagitta a smooth curve through
// the neighbouring knots has (chord_sagitta) plus this much, or the knots' resolution when that
// is larger, before the interval takes the shape-preserving cubic instead, m. A flank exported
// with one or two chords over its involute (FreeCAD at 0.1 mm deflection: 1.6 mm chords on a
// module-1 tooth) has knots on the involute but so far apart that the cubic through them reaches
// for the fillet's curvature and bows 114–229 µm off a chord the involute leaves by 43 µm; on
// every finer mesh of the MCAD and FreeCAD corpora the cubic stays within twice the sagitta.
constexpr double kBowAllowance_m = 0.5e-6;

// Point of a knot in its tooth's frame.
struct Knot {
  double r, theta;
};

double lagrange(const std::vector<double>& x, const std::vector<double>& y, std::size_t j, double at) {
  double value = 0;
  for (std::size_t a = j; a < j + 4; ++a) {
    double w = 1;
    for (std::size_t b = j; b < j + 4; ++b)
      if (b != a) w *= (at - x[b]) / (x[a] - x[b]);
    value += w * y[a];
  }
  return value;
}

// Fritsch–Carlson derivative at knot i of (x, y).
double pchip_slope(const std::vector<double>& x, const std::vector<double>& y, std::size_t i) {
  const std::size_t n = x.size();
  auto secant = [&](std::size_t a) { return (y[a + 1] - y[a]) / (x[a + 1] - x[a]); };
  if (i == 0) return secant(0);
  if (i == n - 1) return secant(n - 2);
  const double d0 = secant(i - 1), d1 = secant(i);
  if (d0 * d1 <= 0) return 0.0;
  const double h0 = x[i] - x[i - 1], h1 = x[i + 1] - x[i];
  const double w1 = 2 * h1 + h0, w2 = h1 + 2 * h0;
  return (w1 + w2) / (w1 / d0 + w2 / d1);
}

// Third divided difference of (x, y) over knots s..s+3: the leading coefficient of their cubic.
double third_difference(const std::vector<double>& x, const std::vector<double>& y, std::size_t s) {
  auto d1 = [&](std::size_t a) { return (y[a + 1] - y[a]) / (x[a + 1] - x[a]); };
  auto d2 = [&](std::size_t a) { return (d1(a + 1) - d1(a)) / (x[a + 2] - x[a]); };
  return (d2(s + 1) - d2(s)) / (x[s + 3] - x[s]);
}

// The stencil of four knots for interval j (knots s..s+3, j and j+1 among them): the centred
// one (s = j − 1, clamped to the ends), unless a stencil shifted by one knot has a third
// divided difference kStencilRatio times smaller — the centred cubic then spans a jump of the
// curve's curvature (an involute meeting its fillet) that the shifted one, on one side of it,
// does not (the idea of ENO interpolation, Harten et al. 1987, held to where it matters).
std::size_t stencil(const std::vector<double>& x, const std::vector<double>& y, std::size_t j) {
  const std::size_t n = x.size(), centred = std::clamp<std::size_t>(j + 1, 2, n - 2) - 2;
  const double d_c = std::abs(third_difference(x, y, centred));
  std::size_t best = centred;
  double d_best = d_c;
  for (std::size_t cand : {centred - 1, centred + 1}) {
    if (cand > n - 4 || cand > j || cand + 3 < j + 1) continue;  // (centred − 1 wraps for 0)
    const double d = std::abs(third_difference(x, y, cand));
    if (d * kStencilRatio < d_c && d < d_best) best = cand, d_best = d;
  }
  return best;
}

double hermite(const std::vector<double>& x, const std::vector<double>& y, std::size_t j, double m0, double m1, double at) {
  const double h = x[j + 1] - x[j], t = (at - x[j]) / h, t2 = t * t, t3 = t2 * t;
  return (2 * t3 - 3 * t2 + 1) * y[j] + (t3 - 2 * t2 + t) * h * m0 + (-2 * t3 + 3 * t2) * y[j + 1] + (t3 - t2) * h * m1;
}

Eigen::Vector2d point(double r, double theta) { return {r * std::cos(theta), r * std::sin(theta)}; }

// Sagitta of a chord of length L on the circle through three points (0 when they are collinear).
double sagitta(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c, double L) {
  const double ab = (b - a).norm(), bc = (c - b).norm(), ca = (a - c).norm();
  const double cross = std::abs((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
  if (cross <= 0) return 0.0;
  const double rho = ab * bc * ca / (2 * cross);
  if (L >= 2 * rho) return rho;
  return rho - std::sqrt(rho * rho - 0.25 * L * L);
}

// The sagitta a smooth curve through knots j and j+1 has over their chord: the larger of the
// circles through the chord and either neighbouring knot, m.
double chord_sagitta(const std::vector<Eigen::Vector2d>& p, std::size_t j) {
  const double L = (p[j + 1] - p[j]).norm();
  double expected = 0;
  if (j > 0) expected = std::max(expected, sagitta(p[j - 1], p[j], p[j + 1], L));
  if (j + 2 < p.size()) expected = std::max(expected, sagitta(p[j], p[j + 1], p[j + 2], L));
  return expected;
}

// Distance of the point (r, θ) from the chord p0–p1, m.
double off_chord(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1, double r, double theta) {
  const Eigen::Vector2d chord = p1 - p0, q = point(r, theta) - p0;
  return std::abs(chord.x() * q.y() - chord.y() * q.x()) / chord.norm();
}

std::vector<Eigen::Vector2d> knot_points(const FlankKnots& k) {
  std::vector<Eigen::Vector2d> p(k.r_m.size());
  for (std::size_t j = 0; j < p.size(); ++j) p[j] = point(k.r_m[j], k.theta_rad[j]);
  return p;
}

}  // namespace

std::vector<FlankKnots> flank_knots(const Polygon2& loop, const ToothLayout& layout, bool internal, double merge_m) {
  std::vector<Eigen::Vector2d> pts = loop.points;
  if (signed_area(loop) < 0) std::reverse(pts.begin(), pts.end());
  const std::size_t n = pts.size();
  const double pitch = 2 * kPi / layout.teeth;
  std::vector<int> tooth_of(n);
  std::vector<Knot> knot(n);
  for (std::size_t q = 0; q < n; ++q) {
    const double phi = std::atan2(pts[q].y(), pts[q].x()) - layout.tooth0_angle_rad;
    const long k = std::lround(phi / pitch);
    tooth_of[q] = static_cast<int>(((k % layout.teeth) + layout.teeth) % layout.teeth);
    knot[q] = {pts[q].norm(), std::remainder(phi - static_cast<double>(k) * pitch, 2 * kPi)};
  }
  // Longest runs per (tooth, side), as lists of loop indices.
  std::vector<std::vector<std::size_t>> best(static_cast<std::size_t>(layout.teeth) * 2);
  std::vector<std::size_t> run;
  for (int dir : {+1, -1}) {
    for (std::size_t q = 0; q < n;) {
      run.assign(1, q);
      std::size_t next = q + 1;
      for (; next < q + n; ++next) {
        const std::size_t at = next % n, last = run.back();
        if (tooth_of[at] != tooth_of[q]) break;
        const double rise = dir * (knot[at].r - knot[last].r), step = (pts[at] - pts[last]).norm();
        if (step <= merge_m) continue;  // too close to the last knot to tell apart
        if (rise <= kMinKnotRise_m || rise <= kMinFlankSlope * step) break;
        run.push_back(at);
      }
      // Ascending r along the loop: Cw side of an external tooth, Ccw side of an internal one.
      const bool cw_side = (dir > 0) != internal;
      std::vector<std::size_t>& b = best[static_cast<std::size_t>(tooth_of[q]) * 2 + (cw_side ? 1 : 0)];
      if (run.size() > b.size()) b = run;
      q = std::max(next - 1, q + 1);
    }
  }
  std::vector<FlankKnots> flanks(best.size());
  for (std::size_t f = 0; f < best.size(); ++f) {
    if (best[f].size() < 4)
      throw InputError("flank table: tooth " + std::to_string(f / 2) + " has no " + (f % 2 ? "Cw" : "Ccw") +
                       " flank of at least 4 vertices whose radius grows steadily: the toothed outline is not "
                       "star-shaped about the axis, or the tooth layout (teeth, tooth0) does not match it");
    for (std::size_t q : best[f]) {
      flanks[f].r_m.push_back(knot[q].r);
      flanks[f].theta_rad.push_back(knot[q].theta);
    }
    if (flanks[f].r_m.front() > flanks[f].r_m.back()) {
      std::reverse(flanks[f].r_m.begin(), flanks[f].r_m.end());
      std::reverse(flanks[f].theta_rad.begin(), flanks[f].theta_rad.end());
    }
  }
  return flanks;
}

double knot_resolution_m(const std::vector<FlankKnots>& flanks) {
  std::vector<double> d;
  for (const FlankKnots& k : flanks)
    for (std::size_t j = 2; j + 2 < k.r_m.size(); ++j) {
      std::vector<double> x{k.r_m[j - 2], k.r_m[j - 1], k.r_m[j + 1], k.r_m[j + 2]};
      std::vector<double> y{k.theta_rad[j - 2], k.theta_rad[j - 1], k.theta_rad[j + 1], k.theta_rad[j + 2]};
      d.push_back(std::abs(lagrange(x, y, 0, k.r_m[j]) - k.theta_rad[j]) * k.r_m[j]);
    }
  if (d.empty()) return 0.0;
  std::nth_element(d.begin(), d.begin() + static_cast<long>(d.size() / 2), d.end());
  return d[d.size() / 2];
}

void sample_flank(const FlankKnots& k, double r0, double dr, int samples, double* out, double resolution_m) {
  const std::vector<double>&x = k.r_m, &y = k.theta_rad;
  const std::vector<Eigen::Vector2d> p = knot_points(k);
  const double bow_allowance = std::max(kBowAllowance_m, resolution_m);
  std::size_t interval = static_cast<std::size_t>(-1), s = 0;
  bool shape_preserving = false;
  // The Lagrange values the overshoot check computed, for samples [checked_from, checked_to) of
  // the current interval: the same call the sample would make, kept instead of made twice.
  int checked_from = 0, checked_to = 0;
  for (int i = 0; i < samples; ++i) {
    const double r = r0 + i * dr;
    if (r < x.front() || r > x.back()) {  // no material of this flank here
      out[i] = kNaN;
      continue;
    }
    // The knot interval [x[j], x[j+1]] holding r (its stencil of four knots, s, chosen once per interval).
    const std::size_t j =
        std::min<std::size_t>(static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), r) - x.begin()), x.size() - 1) - 1;
    if (j != interval) {
      // Does the Lagrange cubic stay within the interval's knot range, and within twice a smooth
      // curve's sagitta of its chord, at every sample in it?
      interval = j;
      s = stencil(x, y, j);
      shape_preserving = false;
      const double lo = std::min(y[j], y[j + 1]) - kOvershoot_rad, hi = std::max(y[j], y[j + 1]) + kOvershoot_rad;
      const double max_bow = 2 * chord_sagitta(p, j) + bow_allowance;
      checked_from = checked_to = i;
      for (int m = i; m < samples && r0 + m * dr <= x[j + 1]; ++m) {
        const double v = lagrange(x, y, s, r0 + m * dr);
        if (v < lo || v > hi || off_chord(p[j], p[j + 1], r0 + m * dr, v) > max_bow) {
          shape_preserving = true;
          break;
        }
        out[m] = v;
        checked_to = m + 1;
      }
    }
    if (shape_preserving)
      out[i] = hermite(x, y, j, pchip_slope(x, y, j), pchip_slope(x, y, j + 1), r);
    else if (!(i >= checked_from && i < checked_to))
      out[i] = lagrange(x, y, s, r);
  }
}

FlankDeparture flank_departure(const FlankKnots& k, double r0, double dr, int samples, const double* values) {
  FlankDeparture worst;
  const std::vector<Eigen::Vector2d> p = knot_points(k);
  for (std::size_t j = 0; j + 1 < p.size(); ++j) {
    const double expected = chord_sagitta(p, j);
    const int first = std::max(0, static_cast<int>(std::ceil((k.r_m[j] - r0) / dr)));
    for (int i = first; i < samples && r0 + i * dr <= k.r_m[j + 1]; ++i) {
      if (std::isnan(values[i])) continue;
      const double off = off_chord(p[j], p[j + 1], r0 + i * dr, values[i]) - expected;
      if (off > worst.departure_m) worst = {off, r0 + i * dr};
    }
  }
  return worst;
}

}  // namespace gearsim::contact
