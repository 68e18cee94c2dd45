#include "geometry/gear_recognition.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <numbers>
#include <sstream>

#include "geometry/involute.hpp"
#include "geometry/constants.hpp"

namespace gearsim {
namespace {

using gearsim::constants::kPi;

// Samples of a loop's radius r(θ) over one turn: 16 per pitch at the most teeth looked for.
constexpr int kSamples = 16384;
constexpr int kMaxTeeth = kSamples / 16;
// Fewest teeth looked for: below five a polygon (a square, a triangle) has a tooth-like wave.
constexpr int kMinTeeth = 5;
// A loop whose radius varies by less than this fraction of its mean is a circle (a bore, a web
// hole, a faceted rim), not teeth: teeth 2.25 modules deep on 1000 teeth vary by 0.45 %.
constexpr double kMinRelativeDepth = 0.002;
// The z-fold wave's amplitude, as a fraction of the depth: a tooth's is about half the depth
// (a square wave's is 0.64), a loop with a bump or a keyway has almost none at z ≥ 3.
constexpr double kMinFundamental = 0.15;
// rms of r(θ) − r(θ + 2π/z) as a fraction of the depth: one damaged tooth passes, a loop that
// only roughly repeats does not.
constexpr double kMaxSymmetryResidual = 0.05;
// Depth over the pitch arc at the mean radius: 0.5–0.8 for teeth of any standard, < 0.05 for
// the facets of a polygonal circle.
constexpr double kMinDepthToPitch = 0.2;
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
// A standard (m, α) matches when m·cos α agrees with the measured base pitch / π to this
// fraction (14.5° and 15° differ by 0.23 %; a 2 µm error of r_b on a 5 mm base circle is 0.04 %).
constexpr double kStandardMatch = 1e-3;

// Modules of ISO 54 (series I and II) and DIN 780 fine modules, mm.
constexpr std::array kModules_mm = {0.05, 0.06, 0.07, 0.08, 0.09, 0.1,  0.11, 0.12,  0.14, 0.15, 0.16, 0.18, 0.2,
                                    0.22, 0.25, 0.28, 0.3,  0.35, 0.4,  0.45, 0.5,   0.55, 0.6,  0.65, 0.7,  0.75,
                                    0.8,  0.85, 0.9,  0.95, 1.0,  1.125, 1.25, 1.375, 1.5,  1.75, 2.0,  2.25, 2.5,
                                    2.75, 3.0,  3.5,  4.0,  4.5,  5.0,  5.5,  6.0,   7.0,  8.0,  9.0,  10.0, 11.0,
                                    12.0, 14.0, 16.0, 18.0, 20.0, 22.0, 25.0, 28.0,  32.0, 36.0, 40.0, 45.0, 50.0};
// Diametral pitches, 1/in (module = 25.4 mm / P).
constexpr std::array kDiametralPitches = {1.0,  1.25, 1.5,  1.75, 2.0,  2.25, 2.5,  3.0,  4.0,  5.0,
                                          6.0,  8.0,  10.0, 12.0, 14.0, 16.0, 18.0, 20.0, 24.0, 32.0,
                                          40.0, 48.0, 64.0, 72.0, 80.0, 96.0, 120.0, 128.0, 200.0};
constexpr std::array kPressureAngles_deg = {14.5, 15.0, 16.0, 17.5, 18.0, 20.0, 22.5, 25.0, 28.0, 30.0};
// Tooth depth of the ISO 53 basic rack (addendum 1 + dedendum 1.25), in modules.
constexpr double kRackDepth = 2.25;
// Base radii of the two flank sides further apart than this fraction make an asymmetric tooth:
// 1e-3 is 10 µm on a 10 mm base circle, beyond any fit of a symmetric one (the corpus: ≤ 1.2 µm)
// and as much as kStandardMatch allows between (m, α) readings.
constexpr double kAsymmetry = 1e-3;
// Weight of a candidate's |profile shift| against its relative depth error when choosing (m, α):
// 0.2 makes a shift of 0.5 (about the largest in use) cost as much as a depth 10 % off 2.25 m.
constexpr double kShiftWeight = 0.2;

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

double wrap_pi(double a) { return std::remainder(a, 2 * kPi); }

// Area centroid of a simple polygon (either orientation), relative to its first point for precision.
Eigen::Vector2d area_centroid(const Polygon2& p) {
  const Eigen::Vector2d o = p.points.front();
  double a2 = 0;
  Eigen::Vector2d c = Eigen::Vector2d::Zero();
  for (std::size_t i = 0; i < p.points.size(); ++i) {
    const Eigen::Vector2d u = p.points[i] - o, v = p.points[(i + 1) % p.points.size()] - o;
    const double w = cross(u, v);
    a2 += w;
    c += w * (u + v);
  }
  return o + c / (3 * a2);
}

struct Tables {
  std::vector<double> cos_t, sin_t;
  Tables() : cos_t(kSamples), sin_t(kSamples) {
    for (int i = 0; i < kSamples; ++i) cos_t[i] = std::cos(2 * kPi * i / kSamples), sin_t[i] = std::sin(2 * kPi * i / kSamples);
  }
};
const Tables& tables() {
  static const Tables t;
  return t;
}

// r(θ_i), θ_i = 2πi/N, about c: the farthest crossing of each ray for the outer loop, the nearest
// for a hole. Empty when some ray misses the loop (c outside it).
std::vector<double> radial_envelope(const Polygon2& p, const Eigen::Vector2d& c, bool outer) {
  const Tables& t = tables();
  std::vector<double> env(kSamples, std::nan(""));
  const double step = 2 * kPi / kSamples;
  const std::size_t n = p.points.size();
  for (std::size_t j = 0; j < n; ++j) {
    const Eigen::Vector2d a = p.points[j] - c, e = p.points[(j + 1) % n] - p.points[j];
    const double ta = std::atan2(a.y(), a.x());
    const Eigen::Vector2d b = a + e;
    const double d = wrap_pi(std::atan2(b.y(), b.x()) - ta);
    const double lo = std::min(ta, ta + d), hi = std::max(ta, ta + d);
    for (long i = static_cast<long>(std::ceil(lo / step)); i <= static_cast<long>(std::floor(hi / step)); ++i) {
      const int k = static_cast<int>(((i % kSamples) + kSamples) % kSamples);
      const Eigen::Vector2d dir(t.cos_t[k], t.sin_t[k]);
      const double den = cross(dir, e);
      if (den == 0) continue;
      const double r = cross(a, e) / den;
      if (!(r > 0)) continue;
      double& slot = env[k];
      if (std::isnan(slot) || (outer ? r > slot : r < slot)) slot = r;
    }
  }
  for (double r : env)
    if (std::isnan(r)) return {};
  return env;
}

// Amplitude of the k-fold wave of r(θ), m.
double amplitude(const std::vector<double>& env, int k) {
  const Tables& t = tables();
  double re = 0, im = 0;
  for (int i = 0; i < kSamples; ++i) {
    const int j = static_cast<int>((static_cast<long>(k) * i) % kSamples);
    re += env[i] * t.cos_t[j];
    im -= env[i] * t.sin_t[j];
  }
  return 2 * std::hypot(re, im) / kSamples;
}

double interpolate(const std::vector<double>& env, double x) {
  const double f = std::floor(x);
  const int i0 = static_cast<int>(((static_cast<long>(f) % kSamples) + kSamples) % kSamples);
  const double w = x - f;
  return (1 - w) * env[i0] + w * env[(i0 + 1) % kSamples];
}

// rms of r(θ) − r(θ + 2π/k), m.
double symmetry_residual(const std::vector<double>& env, int k) {
  const double shift = static_cast<double>(kSamples) / k;
  double s = 0;
  for (int i = 0; i < kSamples; ++i) {
    const double d = env[i] - interpolate(env, i + shift);
    s += d * d;
  }
  return std::sqrt(s / kSamples);
}

// A loop's teeth, if it has any: count, wave amplitude, symmetry and the envelope about its centroid.
struct LoopTeeth {
  int teeth = 0;
  double amplitude_m = 0, residual_m = 0, r_min = 0, r_max = 0;
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  std::vector<double> env;
  std::string why;  // why not, when teeth == 0
};

LoopTeeth loop_teeth(const Polygon2& p, bool outer) {
  LoopTeeth lt;
  if (p.points.size() < 6) return lt.why = "too few points", lt;
  lt.centre = area_centroid(p);
  lt.env = radial_envelope(p, lt.centre, outer);
  if (lt.env.empty()) return lt.why = "does not surround its own centroid", lt;
  const auto [lo, hi] = std::minmax_element(lt.env.begin(), lt.env.end());
  lt.r_min = *lo, lt.r_max = *hi;
  const double depth = lt.r_max - lt.r_min, mean = 0.5 * (lt.r_max + lt.r_min);
  std::ostringstream why;
  if (depth < kMinRelativeDepth * mean) {
    why << "a circle (radius varies by " << depth * 1e6 << " um)";
    return lt.why = why.str(), lt;
  }
  int best = 0;
  for (int k = kMinTeeth; k <= kMaxTeeth; ++k) {
    const double a = amplitude(lt.env, k);
    if (a > lt.amplitude_m) lt.amplitude_m = a, best = k;
  }
  lt.residual_m = symmetry_residual(lt.env, best);
  const double pitch_arc = 2 * kPi * mean / best;
  if (lt.amplitude_m < kMinFundamental * depth)
    why << "no tooth wave (strongest " << best << "-fold amplitude " << lt.amplitude_m / depth << " of the depth)";
  else if (lt.residual_m > kMaxSymmetryResidual * depth)
    why << "not " << best << "-fold symmetric (rms difference between neighbouring pitches " << lt.residual_m * 1e6
        << " um, " << lt.residual_m / depth * 100 << " % of the depth)";
  else if (depth < kMinDepthToPitch * pitch_arc)
    why << "a " << best << "-sided polygon (depth " << depth / pitch_arc << " of the pitch), not teeth";
  else lt.teeth = best;
  lt.why = why.str();
  return lt;
}

// Each tooth's crossings of the mid-depth circle (polar angles about the loop's centre, the
// second past the first): an up- then the next down-crossing for an external tooth (its
// material beyond mid), a down- then the next up-crossing for an internal one. Empty when the
// crossings do not pair up into z teeth.
std::vector<std::pair<double, double>> tooth_crossings(const LoopTeeth& lt, bool internal) {
  const double mid = 0.5 * (lt.r_min + lt.r_max), step = 2 * kPi / kSamples;
  std::vector<double> up, down;
  for (int i = 0; i < kSamples; ++i) {
    const double a = lt.env[i] - mid, b = lt.env[(i + 1) % kSamples] - mid;
    if ((a < 0) == (b < 0)) continue;
    const double theta = (i + a / (a - b)) * step;
    (a < 0 ? up : down).push_back(theta);
  }
  if (static_cast<int>(up.size()) != lt.teeth || static_cast<int>(down.size()) != lt.teeth) return {};
  const std::vector<double>& enter = internal ? down : up;
  const std::vector<double>& leave = internal ? up : down;
  std::vector<std::pair<double, double>> teeth;
  for (double a : enter) {
    double d = 1e300;
    for (double c : leave) d = std::min(d, c - a + (c < a ? 2 * kPi : 0));
    teeth.emplace_back(a, a + d);
  }
  return teeth;
}

// Tooth 0's centre line: the mean of the teeth's mid-crossing angles, modulo the pitch.
double tooth0_angle(const std::vector<std::pair<double, double>>& teeth) {
  std::complex<double> sum = 0;
  const double z = static_cast<double>(teeth.size());
  for (const auto& [a, b] : teeth) sum += std::polar(1.0, z * 0.5 * (a + b));
  return wrap_pi(std::arg(sum)) / z;
}

// The axis: the common centre of the tip and root circles, fitted (least squares, Kåsa's
// linear form with one radius term per circle) to the loop's vertices within 2 % of the depth of
// the tip and of the root circle. A damaged or modified flank moves its points along circles
// about the axis (a flank offset is a rotation), so tip lands and root arcs stay on them; the
// loop's centroid does not (it moves ~1.6 µm toward the paper's 43 µm flank error on z 36).
Eigen::Vector2d refined_axis(const Polygon2& loop, const LoopTeeth& lt) {
  const double band = 0.02 * (lt.r_max - lt.r_min);
  Eigen::Matrix4d A = Eigen::Matrix4d::Zero();
  Eigen::Vector4d rhs = Eigen::Vector4d::Zero();
  int n_tip = 0, n_root = 0;
  for (const Eigen::Vector2d& v : loop.points) {
    const Eigen::Vector2d q = v - lt.centre;
    const double r = q.norm();
    const bool tip = r >= lt.r_max - band, root = r <= lt.r_min + band;
    if (!tip && !root) continue;
    (tip ? n_tip : n_root) += 1;
    // x² + y² + D·x + E·y + F_tip|root = 0
    const Eigen::Vector4d row(q.x(), q.y(), tip ? 1.0 : 0.0, tip ? 0.0 : 1.0);
    A += row * row.transpose();
    rhs -= row * q.squaredNorm();
  }
  if (n_tip < 3 || n_root < 3) return lt.centre;
  const Eigen::Vector4d x = A.ldlt().solve(rhs);
  return lt.centre - 0.5 * Eigen::Vector2d(x(0), x(1));
}

// Points of one side of the teeth in tooth frames: radius and half-angle from the centre line.
struct FlankPoints {
  std::vector<double> r, y;
  std::vector<int> tooth;
};

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
    if (f1 < f2) b = x2, x2 = x1, f2 = f1, x1 = b - g * (b - a), f1 = fit_at(f, use, sigma, x1, &c);
    else a = x1, x1 = x2, f1 = f2, x2 = a + g * (b - a), f2 = fit_at(f, use, sigma, x2, &c);
  }
  return 0.5 * (a + b);
}

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
  if (!select(kTipMargin, g.internal ? kRootMarginInternal : kRootMarginExternal) &&
      !select(kTipMarginWide, kRootMarginWide))
    return fit;
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
    if (e <= tol) fit.active_from_m = std::min(fit.active_from_m, f.r[i]), fit.active_to_m = std::max(fit.active_to_m, f.r[i]);
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

// Tooth thickness at the reference circle m·z/2 of a candidate module, from the two flank fits, m.
double reference_thickness(const RecognisedGear& g, double module_m) {
  const double sigma = g.internal ? -1.0 : 1.0, r = 0.5 * module_m * g.teeth;
  const double half_ccw = g.ccw.base_half_angle_rad - sigma * inv_at(g.ccw.base_radius_m, r);
  const double half_cw = g.cw.base_half_angle_rad - sigma * inv_at(g.cw.base_radius_m, r);
  return r * (half_ccw + half_cw);
}

// Profile shift coefficient of a candidate (m, α): the reference thickness beyond half the pitch,
// over 2·m·tan α (ISO 21771, external gears). For a ring the same formula on its tooth gives the
// shift's size; its sign convention varies, so only the size is used (to choose m and α).
double profile_shift(const RecognisedGear& g, double module_m, double pressure_angle_rad) {
  return (reference_thickness(g, module_m) / module_m - 0.5 * kPi) / (2 * std::tan(pressure_angle_rad));
}

// Module and pressure angle from the base pitch, the depth and the tooth thickness (see
// RecognisedGear::standard). Every standard (m, α) with m·cos α on the base pitch is a valid
// reading of the same involutes (a change of α is a change of profile shift); the one chosen
// needs the least departure from a standard gear: its depth nearest 2.25 m and its profile shift
// nearest 0, weighted kShiftWeight per unit of shift. E.g. a 60-tooth ring of m 1 mm, 25° with a
// 2.05 m stub depth also reads as m 0.95 mm, 17.5° with depth 2.16 m — but a shift of 1.9.
void module_and_pressure_angle(RecognisedGear& g) {
  const double mcos = g.base_pitch_m / kPi, m_depth = std::abs(g.root_radius_m - g.tip_radius_m) / kRackDepth;
  double best_score = 1e300;
  auto consider = [&](double m) {
    if (m < 0.75 * m_depth || m > 1.33 * m_depth) return;
    for (double a_deg : kPressureAngles_deg) {
      const double a = a_deg * kPi / 180;
      if (std::abs(m * std::cos(a) - mcos) > kStandardMatch * mcos) continue;
      const double score = std::abs(m / m_depth - 1) + kShiftWeight * std::abs(profile_shift(g, m, a));
      if (score < best_score) best_score = score, g.module_m = m, g.pressure_angle_rad = a, g.standard = true;
    }
  };
  for (double m_mm : kModules_mm) consider(m_mm * 1e-3);
  for (double p : kDiametralPitches) consider(25.4e-3 / p);
  if (!g.standard) {
    g.module_m = m_depth;
    g.pressure_angle_rad = mcos < m_depth ? std::acos(mcos / m_depth) : 0.0;
  }
  g.reference_radius_m = 0.5 * g.module_m * g.teeth;
  g.reference_thickness_m = reference_thickness(g, g.module_m);
  if (!g.internal && g.pressure_angle_rad > 0) g.profile_shift = profile_shift(g, g.module_m, g.pressure_angle_rad);
}

}  // namespace

GearRecognition recognise_gear(const Outline2& outline) {
  GearRecognition out;
  // The toothed loop: the one with the strongest tooth wave among those that have teeth.
  LoopTeeth best;
  int best_loop = -2;
  std::ostringstream why;
  for (int l = -1; l < static_cast<int>(outline.holes.size()); ++l) {
    LoopTeeth lt = loop_teeth(l < 0 ? outline.outer : outline.holes[static_cast<std::size_t>(l)], l < 0);
    if (lt.teeth > 0 && lt.amplitude_m > best.amplitude_m) best = std::move(lt), best_loop = l;
    else if (lt.teeth == 0) why << (why.tellp() > 0 ? "; " : "") << (l < 0 ? "outer loop" : "hole " + std::to_string(l)) << ": " << lt.why;
  }
  if (best_loop == -2) return out.reason = "no loop of the outline has teeth (" + why.str() + ")", out;
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
    m << "the toothed loop repeats " << g.teeth << " times but its mid-depth circle (r = "
      << 0.5 * (best.r_min + best.r_max) * 1e3 << " mm) does not cross it twice per tooth";
    return out.reason = m.str(), out;
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
  out.gear = g;
  return out;
}

Outline2 recentred(const Outline2& outline, const Eigen::Vector2d& axis_m) {
  Outline2 o = outline;
  for (Eigen::Vector2d& v : o.outer.points) v -= axis_m;
  for (Polygon2& h : o.holes)
    for (Eigen::Vector2d& v : h.points) v -= axis_m;
  return o;
}

}  // namespace gearsim
