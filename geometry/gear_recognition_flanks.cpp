// Gear recognition, the flanks: the toothed loop's points in tooth frames, split by side, and
// one involute fitted to each side (base radius by a scan and golden-section search, outliers
// dropped by robust sigmas). Not the choice of module and pressure angle
// (gear_recognition_standard.cpp).
#include <algorithm>
#include <array>
#include <cmath>

#include "geometry/gear_recognition_detail.hpp"
#include "geometry/involute.hpp"

namespace gearsim::recognition_detail {
namespace {

// Involute fits: the radial window the first fit uses, as fractions of the depth from the tip
// and from the root (clear of tip corners, fillets and undercut for z ≥ 8 at 14.5°).
constexpr double kTipMargin = 0.1;
constexpr double kRootMarginExternal = 0.6;
constexpr double kRootMarginInternal = 0.4;
// When that window holds fewer than three distinct radii (coarse facets: 5 per involute leave one
// vertex per flank between 60 % and 90 % of the depth, and an involute through points of a single
// radius fits any base circle), the fit widens to this window, relying on the outlier passes to
// drop fillet and tip-corner points; distinct means radii differing by this fraction of the depth.
constexpr double kTipMarginWide = 0.02;
constexpr double kRootMarginWide = 0.1;
constexpr double kDistinctRadius = 1e-3;
// A flank is an involute when its kept points lie within this rms of the fit, m (ASCII STL
// quantisation and CAD noise are ≤ 0.5 µm) and at most this fraction of them are outliers.
constexpr double kInvoluteFitTolerance_m = 2e-6;
constexpr double kMaxOutlierFraction = 0.25;
// Points further from the fit than max(this many robust sigmas, kOutlierFloor_m) are outliers.
constexpr double kOutlierSigmas = 6.0;
constexpr double kOutlierFloor_m = 0.5e-6;

// Least-squares involute through (r, y) over `use`: y = c − σ·inv(r_b, r). Returns angular SSE.
double fit_at(const FlankPoints& f, const std::vector<int>& use, double sigma, double rb, double* c) {
  double sum = 0;
  for (int i : use) sum += f.y[i] + sigma * inv_at(rb, f.r[i]);
  *c = sum / static_cast<double>(use.size());
  double sse = 0;
  for (int i : use) {
    const double e = f.y[i] + sigma * inv_at(rb, f.r[i]) - *c;
    sse += e * e;
  }
  return sse;
}

// r_b minimising the fit over (0.3·r_lo, r_lo): a scan, then golden-section refinement.
double best_base_radius(const FlankPoints& f, const std::vector<int>& use, double sigma) {
  double r_lo = 1e300, c = 0;
  for (int i : use) r_lo = std::min(r_lo, f.r[i]);
  const int n = 256;
  const double a0 = 0.3 * r_lo, h = (r_lo - a0) / n;
  int best = 0;
  double best_sse = 1e300;
  for (int i = 0; i <= n; ++i) {
    const double sse = fit_at(f, use, sigma, a0 + i * h, &c);
    if (sse < best_sse) best_sse = sse, best = i;
  }
  double a = a0 + std::max(0, best - 1) * h, b = a0 + std::min(n, best + 1) * h;
  const double g = 0.5 * (std::sqrt(5.0) - 1);
  double x1 = b - g * (b - a), x2 = a + g * (b - a);
  double f1 = fit_at(f, use, sigma, x1, &c), f2 = fit_at(f, use, sigma, x2, &c);
  for (int it = 0; it < 100 && b - a > 1e-12 * r_lo; ++it) {
    if (f1 < f2)
      b = x2, x2 = x1, f2 = f1, x1 = b - g * (b - a), f1 = fit_at(f, use, sigma, x1, &c);
    else
      a = x1, x1 = x2, f1 = f2, x2 = a + g * (b - a), f2 = fit_at(f, use, sigma, x2, &c);
  }
  return 0.5 * (a + b);
}

}  // namespace

std::array<FlankPoints, 2> flank_points(const Polygon2& loop, const RecognisedGear& g) {
  std::array<FlankPoints, 2> sides;  // [0] Ccw, [1] Cw
  const double pitch = 2 * kPi / g.teeth;
  for (const Eigen::Vector2d& v : loop.points) {
    const Eigen::Vector2d q = v - g.axis_m;
    const double rel0 = std::atan2(q.y(), q.x()) - g.tooth0_angle_rad;
    const long k = std::lround(rel0 / pitch);
    const double rel = rel0 - static_cast<double>(k) * pitch;
    FlankPoints& s = sides[rel < 0];
    s.r.push_back(q.norm());
    s.y.push_back(std::abs(rel));
    s.tooth.push_back(static_cast<int>(((k % g.teeth) + g.teeth) % g.teeth));
  }
  return sides;
}

double inv_at(double rb, double r) { return involute(std::acos(std::min(1.0, rb / r))); }

InvoluteFit fit_flank(const FlankPoints& f, const RecognisedGear& g) {
  InvoluteFit fit;
  const double sigma = g.internal ? -1.0 : 1.0;
  const double depth = std::abs(g.root_radius_m - g.tip_radius_m);
  double lo = 0, hi = 0;
  std::vector<int> window;
  auto select = [&](double tip_margin, double root_margin) {
    lo = g.internal ? g.tip_radius_m + tip_margin * depth : g.root_radius_m + root_margin * depth;
    hi = g.internal ? g.root_radius_m - root_margin * depth : g.tip_radius_m - tip_margin * depth;
    window.clear();
    std::vector<double> radii;
    for (int i = 0; i < static_cast<int>(f.r.size()); ++i)
      if (f.r[i] >= lo && f.r[i] <= hi) window.push_back(i), radii.push_back(f.r[i]);
    std::sort(radii.begin(), radii.end());
    int distinct = radii.empty() ? 0 : 1;
    for (std::size_t i = 1; i < radii.size(); ++i)
      if (radii[i] - radii[i - 1] > kDistinctRadius * depth) ++distinct;
    return distinct >= 3 && window.size() >= 4;
  };
  if (!select(kTipMargin, g.internal ? kRootMarginInternal : kRootMarginExternal) && !select(kTipMarginWide, kRootMarginWide)) return fit;
  std::vector<int> use = window;
  double rb = 0, c = 0;
  for (int pass = 0; pass < 4; ++pass) {
    rb = best_base_radius(f, use, sigma);
    fit_at(f, use, sigma, rb, &c);
    std::vector<double> dev;
    for (int i : use) dev.push_back(std::abs(f.y[i] + sigma * inv_at(rb, f.r[i]) - c) * rb);
    std::nth_element(dev.begin(), dev.begin() + dev.size() / 2, dev.end());
    const double limit = std::max(kOutlierSigmas * 1.4826 * dev[dev.size() / 2], kOutlierFloor_m);
    std::vector<int> kept;
    for (int i : window)
      if (std::abs(f.y[i] + sigma * inv_at(rb, f.r[i]) - c) * rb <= limit) kept.push_back(i);
    if (kept == use || kept.size() < 4) break;
    use = kept;
  }
  fit_at(f, use, sigma, rb, &c);
  double sse = 0;
  for (int i : use) sse += std::pow((f.y[i] + sigma * inv_at(rb, f.r[i]) - c) * rb, 2);
  fit.base_radius_m = rb;
  fit.base_half_angle_rad = c;
  fit.points = static_cast<int>(use.size());
  fit.rms_m = std::sqrt(sse / static_cast<double>(use.size()));
  // Outliers (in the window, off the fit) and the active range (all points on the involute).
  const double tol = std::max(3 * fit.rms_m, 1e-6);
  fit.active_from_m = 1e300;
  for (int i = 0; i < static_cast<int>(f.r.size()); ++i) {
    const double e = f.r[i] >= rb ? std::abs(f.y[i] + sigma * inv_at(rb, f.r[i]) - c) * rb : 1e300;
    const bool in_window = f.r[i] >= lo && f.r[i] <= hi;
    if (e <= tol)
      fit.active_from_m = std::min(fit.active_from_m, f.r[i]), fit.active_to_m = std::max(fit.active_to_m, f.r[i]);
    else if (in_window) {
      if (std::find(fit.outlier_teeth.begin(), fit.outlier_teeth.end(), f.tooth[i]) == fit.outlier_teeth.end())
        fit.outlier_teeth.push_back(f.tooth[i]);
      fit.largest_outlier_m = std::max(fit.largest_outlier_m, e);
    }
  }
  std::sort(fit.outlier_teeth.begin(), fit.outlier_teeth.end());
  fit.involute = fit.rms_m <= kInvoluteFitTolerance_m &&
                 static_cast<double>(window.size() - use.size()) <= kMaxOutlierFraction * static_cast<double>(window.size());
  return fit;
}

}  // namespace gearsim::recognition_detail
