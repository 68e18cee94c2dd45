#include "contact/flank_table.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/errors.hpp"
#include "contact/flank_knots.hpp"
#include "geometry/constants.hpp"

namespace gearsim::contact {
namespace {

using gearsim::constants::kNaN;
using gearsim::constants::kPi;

// Radial margin kept inside the loop's extent, as a share of it: the root and tip arcs are
// chords whose sagitta dips below the nominal circle; 1e-4 of a 2 mm tooth is 0.2 µm.
constexpr double kEdgeShare = 1e-4;

// Half-width, in samples, of the central difference for dθ/dr (see sample()).
constexpr int kSlopeSpan = 2;

// Teeth whose flanks differ by less than this everywhere share their table rows, m (as an arc at
// the tip). Normally 0.1 nm: 5000 times below the 0.5 µm outline accuracy, far above the 1e-14 m
// rounding between a generated gear's rotated copies of one tooth.
constexpr double kSharedToothTolerance_m = 1e-10;

// Flank vertices closer than this to the last knot are passed over, m: float32 noise of an
// imported outline (~1e-9 m at gear scale) must not make a knot of its own.
constexpr double kKnotSpacing_m = 1e-8;

// Vertices closer than this many times the outline's measured resolution (knot_resolution_m)
// are merged: at that spacing their noise, not the flank, sets the slope between them.
constexpr double kNoiseMerge = 4;

}  // namespace

FlankTable::FlankTable(const Polygon2& loop, const ToothLayout& layout, bool internal, int samples)
    : layout_(layout), internal_(internal), pitch_(2 * kPi / layout.teeth), samples_(samples) {
  if (layout.teeth < 3) throw InputError("flank table: tooth layout needs at least 3 teeth");
  if (samples < 16) throw InputError("flank table: at least 16 radial samples");
  double rmin = 1e300, rmax = 0;
  for (const Eigen::Vector2d& p : loop.points) {
    rmin = std::min(rmin, p.norm());
    rmax = std::max(rmax, p.norm());
  }
  const double margin = kEdgeShare * (rmax - rmin);
  r_min_ = rmin + margin;
  r_max_ = rmax - margin;
  dr_ = (r_max_ - r_min_) / (samples - 1);
  inv_dr_ = 1 / dr_;
  inv_pitch_ = 1 / pitch_;
  ccw_.assign(static_cast<std::size_t>(layout.teeth) * samples, kNaN);
  cw_ = ccw_;
  // The loop's vertices lie on the true curves (its chords do not): each flank is rebuilt from
  // its vertices as knots of a cubic in r, then sampled (flank_knots.hpp). Knots closer than a
  // few times the outline's measured noise are merged before the cubic sees them.
  std::vector<FlankKnots> flanks = flank_knots(loop, layout, internal, kKnotSpacing_m);
  knot_resolution_m_ = contact::knot_resolution_m(flanks);
  if (kNoiseMerge * knot_resolution_m_ > kKnotSpacing_m) flanks = flank_knots(loop, layout, internal, kNoiseMerge * knot_resolution_m_);
  for (int t = 0; t < layout.teeth; ++t)
    for (int side = 0; side < 2; ++side) {
      const FlankKnots& k = flanks[static_cast<std::size_t>(t) * 2 + side];
      double* row = (side == 0 ? ccw_ : cw_).data() + static_cast<std::size_t>(t) * samples;
      sample_flank(k, r_min_, dr_, samples, row, knot_resolution_m_);
      const FlankDeparture d = flank_departure(k, r_min_, dr_, samples, row);
      if (d.departure_m > departure_.departure_m) departure_ = {d.departure_m, t, side == 0 ? Flank::Ccw : Flank::Cw, d.r_m};
    }
  share_identical_teeth();
  build_extents();
  build_probe_knots();
  probe_points_.resize(static_cast<std::size_t>(layout.teeth) * 2 * kProbeRadii);
  probe_material_.assign(static_cast<std::size_t>(layout.teeth) * 2, 0);
  tooth_centres_.resize(static_cast<std::size_t>(layout.teeth));
  const double r_mid = 0.5 * (r_min_ + r_max_), half = 0.5 * (r_max_ - r_min_);
  const double wide = r_max_ * pitch_ * 0.5;
  tooth_bound_ = std::sqrt(half * half + wide * wide);
  for (int t = 0; t < layout.teeth; ++t) {
    const double a = tooth_angle_rad(t);
    tooth_centres_[static_cast<std::size_t>(t)] = r_mid * Eigen::Vector2d(std::cos(a), std::sin(a));
    for (Flank f : {Flank::Ccw, Flank::Cw})
      for (int i = 0; i < kProbeRadii; ++i) {
        const double r = probe_radius(i);
        const bool material = !std::isnan(flank_angle(t, f, r));
        probe_points_[(static_cast<std::size_t>(t) * 2 + (f == Flank::Cw)) * kProbeRadii + i] =
            material ? flank_point(t, f, r) : Eigen::Vector2d(kNaN, kNaN);
        if (material) probe_material_[static_cast<std::size_t>(t) * 2 + (f == Flank::Cw)] |= std::uint32_t{1} << i;
      }
  }
}

void FlankTable::share_identical_teeth() {
  // Teeth whose two flanks agree everywhere within kSharedToothTolerance_m (as an arc at the tip
  // radius) share one row of each table: a generated gear's teeth all do, and a table that fits
  // the cache is what keeps probing fast. Teeth with errors or CAD noise keep their own rows.
  const double tol = kSharedToothTolerance_m / r_max_;
  const std::size_t n = static_cast<std::size_t>(samples_);
  auto same = [&](const std::vector<double>& table, std::size_t row_a, std::size_t row_b) {
    for (std::size_t i = 0; i < n; ++i) {
      const double u = table[row_a * n + i], v = table[row_b * n + i];
      if (std::isnan(u) != std::isnan(v) || std::abs(u - v) > tol) return false;
    }
    return true;
  };
  std::vector<double> ccw, cw;
  std::vector<std::size_t> kept;  // full-table row of each shared row
  row_of_.assign(static_cast<std::size_t>(layout_.teeth), 0);
  for (std::size_t t = 0; t < row_of_.size(); ++t) {
    std::size_t r = 0;
    while (r < kept.size() && !(same(ccw_, kept[r], t) && same(cw_, kept[r], t))) ++r;
    if (r == kept.size()) {
      kept.push_back(t);
      tooth_of_row_.push_back(static_cast<int>(t));
      ccw.insert(ccw.end(), ccw_.begin() + static_cast<long>(t * n), ccw_.begin() + static_cast<long>((t + 1) * n));
      cw.insert(cw.end(), cw_.begin() + static_cast<long>(t * n), cw_.begin() + static_cast<long>((t + 1) * n));
    }
    row_of_[t] = static_cast<int>(r);
  }
  ccw_ = std::move(ccw);
  cw_ = std::move(cw);
}

double FlankTable::sample(const std::vector<double>& table, int tooth, double r, double* slope) const {
  const double x = (r - r_min_) * inv_dr_;
  // The sample below r (truncation is floor for x ≥ 0; below 0 both clamp to 0), no libm call.
  int i = x < samples_ ? static_cast<int>(x) : samples_;
  i = std::clamp(i, 0, samples_ - 2);
  const double f = x - i;
  const double* row = table.data() + static_cast<std::size_t>(row_of_[static_cast<std::size_t>(tooth)]) * samples_;
  if (slope) {
    // Central difference over ±kSlopeSpan samples of the cubic knots' interpolant; where the
    // span leaves the tooth, the one interval.
    const int lo = std::max(i - kSlopeSpan, 0), hi = std::min(i + 1 + kSlopeSpan, samples_ - 1);
    *slope = (std::isnan(row[lo]) || std::isnan(row[hi])) ? (row[i + 1] - row[i]) * inv_dr_ : (row[hi] - row[lo]) * inv_dr_ / (hi - lo);
  }
  return row[i] + f * (row[i + 1] - row[i]);
}

double FlankTable::flank_angle(int tooth, Flank flank, double r) const {
  return sample(flank == Flank::Ccw ? ccw_ : cw_, tooth, r, nullptr);
}

double FlankTable::flank_slope(int tooth, Flank flank, double r) const {
  double s = 0;
  sample(flank == Flank::Ccw ? ccw_ : cw_, tooth, r, &s);
  return s;
}

// Inline: every call is in this file (flank_jet() makes most of them, ≈ 75 per paper step).
[[gnu::always_inline]] inline Eigen::Vector2d FlankTable::direction(int tooth, double rel) const {
  // cos and sin of the small angle rel (|rel| < half a pitch) by their Taylor series, which at
  // |rel| ≤ 0.25 rad end below 1e-16 (the next terms: 0.25^13/13! = 2.4e-18, 0.25^14/14! = 4e-20);
  // then turned by the tooth's centre-line direction. The same unit vector as the sincos of the
  // summed angle to a few ulp, at a fifth of the cost.
  // The polynomials in x² by Estrin's scheme (x⁴, x⁸ and pairs of terms side by side, not one
  // long Horner chain: this runs on every flank evaluation, where the chain's latency is what
  // costs).
  double c, s;
  if (std::abs(rel) <= 0.25) {
    const double y = rel * rel, y2 = y * y, y4 = y2 * y2;
    s = rel * ((1 + (-1.0 / 6) * y) + y2 * (1.0 / 120 + (-1.0 / 5040) * y) + y4 * (1.0 / 362880 + (-1.0 / 39916800) * y));
    c = (1 + (-0.5) * y) + y2 * (1.0 / 24 + (-1.0 / 720) * y) + y4 * ((1.0 / 40320 + (-1.0 / 3628800) * y) + y2 * (1.0 / 479001600));
  } else {
    c = std::cos(rel);
    s = std::sin(rel);
  }
  const Eigen::Vector2d& axis = tooth_axis_[static_cast<std::size_t>(tooth)];
  return {axis.x() * c - axis.y() * s, axis.y() * c + axis.x() * s};
}

Eigen::Vector2d FlankTable::flank_point(int tooth, Flank flank, double r) const {
  return r * direction(tooth, flank_angle(tooth, flank, r));
}

bool FlankTable::flank_point_if_material(int tooth, Flank flank, double r, Eigen::Vector2d* point) const {
  const double rel = flank_angle(tooth, flank, r);
  if (std::isnan(rel)) return false;
  *point = r * direction(tooth, rel);
  return true;
}

FlankTable::FlankFrame FlankTable::flank_frame(int tooth, Flank flank, double r) const {
  double slope = 0;
  const double rel = sample(flank == Flank::Ccw ? ccw_ : cw_, tooth, r, &slope);
  const Eigen::Vector2d radial = direction(tooth, rel), tangential(-radial.y(), radial.x());
  FlankFrame f;
  f.point = r * radial;
  // d(point)/dr = radial + r·θ'·tangential; the outward normal turns it a quarter turn toward
  // increasing angle for a Ccw flank, decreasing for a Cw flank.
  f.tangent = (radial + r * slope * tangential).normalized();
  const Eigen::Vector2d n(-f.tangent.y(), f.tangent.x());
  f.normal = flank == Flank::Ccw ? n : Eigen::Vector2d(-n);
  return f;
}

void FlankTable::build_extents() {
  extents_.clear();
  for (int tooth : tooth_of_row_)
    for (Flank flank : {Flank::Ccw, Flank::Cw}) {
      const double* row = row_data(tooth, flank);
      int lo = 0, hi = samples_ - 1;
      while (lo < samples_ && std::isnan(row[lo])) ++lo;
      while (hi > lo && std::isnan(row[hi])) --hi;
      extents_.emplace_back(r_min_ + lo * dr_, r_min_ + hi * dr_);
    }
}

namespace {
// The cubic Hermite of sample interval i of a flank's row at t ∈ [0, 1] (flank_jet()): θ and
// its first two derivatives in r. False where either end lacks material.
[[gnu::always_inline]] inline bool hermite(const double* row, int samples, int i, double t, double inv_dr, double* theta, double* th1,
                                           double* th2) {
  const double y0 = row[i], y1 = row[i + 1];
  if (std::isnan(y0) || std::isnan(y1)) return false;
  // Slopes per sample step at i and i + 1: central where both neighbours have material.
  const double ym = i > 0 ? row[i - 1] : kNaN, yp = i + 2 < samples ? row[i + 2] : kNaN;
  const double m0 = std::isnan(ym) ? y1 - y0 : 0.5 * (y1 - ym);
  const double m1 = std::isnan(yp) ? y1 - y0 : 0.5 * (yp - y0);
  // Cubic Hermite in t ∈ [0, 1] and its derivatives, from its power-basis coefficients
  // y0 + m0·t + c2·t² + c3·t³.
  const double c2 = 3 * (y1 - y0) - 2 * m0 - m1, c3 = 2 * (y0 - y1) + m0 + m1;
  *theta = y0 + t * (m0 + t * (c2 + t * c3));
  *th1 = (m0 + t * (2 * c2 + 3 * t * c3)) * inv_dr;  // dθ/dr
  *th2 = (2 * c2 + 6 * t * c3) * inv_dr * inv_dr;  // d²θ/dr²
  return true;
}
}  // namespace

[[gnu::always_inline]] inline bool FlankTable::interval_jet(int tooth, Flank flank, int i, double t, FlankJet* jet, double r) const {
  double theta, th1, th2;
  if (!hermite(row_data(tooth, flank), samples_, i, t, inv_dr_, &theta, &th1, &th2)) return false;
  const Eigen::Vector2d u = direction(tooth, theta), v(-u.y(), u.x());
  // p = r·u(θ(r)): p' = u + r·θ'·v, p'' = (2θ' + r·θ'')·v − r·θ'²·u.
  jet->point = r * u;
  jet->d1 = u + (r * th1) * v;
  jet->d2 = (2 * th1 + r * th2) * v - (r * th1 * th1) * u;
  return true;
}

bool FlankTable::flank_jet(int tooth, Flank flank, double r, FlankJet* jet) const {
  const double x = (r - r_min_) * inv_dr_;
  if (!(x >= 0 && x <= samples_ - 1)) return false;
  int i = std::min(static_cast<int>(x), samples_ - 2);
  double t = x - i;
  if (std::isnan(row_data(tooth, flank)[i + 1]) && t == 0 && i > 0) {  // the flank's last sample: the interval below, at its end
    --i;
    t = 1;
  }
  return interval_jet(tooth, flank, i, t, jet, r);
}

void FlankTable::build_convexity_bands() {
  const int intervals = samples_ - 1;
  const int bands = (intervals + kConvexityBand - 1) / kConvexityBand;
  const std::size_t rows = tooth_of_row_.size(), per_flank = band_levels(bands, convexity_level_start_);
  convexity_block_ = per_flank;
  convexity_bands_.assign(rows * 2 * per_flank, ConvexityRange{kInfinity, -kInfinity});
  for (std::size_t row = 0; row < rows; ++row)
    for (Flank f : {Flank::Ccw, Flank::Cw}) {
      ConvexityRange* out = convexity_bands_.data() + (row * 2 + (f == Flank::Cw)) * per_flank;
      for (int i = 0; i < intervals; ++i) {
        ConvexityRange& band = out[i / kConvexityBand];
        for (double t : {0.0, 1.0 / 3, 2.0 / 3, 1.0}) {
          FlankJet jet;
          const double c = interval_jet(tooth_of_row_[row], f, i, t, &jet, r_min_ + (i + t) * dr_) ? convexity(f, jet) : kNaN;
          if (!std::isfinite(c))
            band = {-kInfinity, kInfinity};  // no material: unbounded
          else if (band.lo != -kInfinity)
            band = {std::min(band.lo, c), std::max(band.hi, c)};  // not already unbounded
        }
      }
      fill_band_runs(out, bands, convexity_level_start_, wider_convexity);
    }
}

FlankTable::ConvexityRange FlankTable::convexity_range(int tooth, Flank flank, double r_lo_m, double r_hi_m) const {
  if (!(r_lo_m >= r_min_ && r_hi_m <= r_max_ && r_lo_m <= r_hi_m)) return {};
  const int last = samples_ - 2;
  const int i_lo = std::min(static_cast<int>((r_lo_m - r_min_) * inv_dr_), last),
            i_hi = std::min(static_cast<int>((r_hi_m - r_min_) * inv_dr_), last);
  const int b_lo = i_lo / kConvexityBand, b_hi = i_hi / kConvexityBand;
  const ConvexityRange* block =
      convexity_bands_.data() +
      (static_cast<std::size_t>(row_of_[static_cast<std::size_t>(tooth)]) * 2 + (flank == Flank::Cw)) * convexity_block_;
  return band_range(block, convexity_level_start_, b_lo, b_hi, wider_convexity);
}

}  // namespace gearsim::contact
