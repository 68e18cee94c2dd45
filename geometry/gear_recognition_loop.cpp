// Gear recognition, the toothed loop: the radial envelope r(θ) of a loop about a centre, the
// tooth count from its strongest z-fold wave (with the checks that tell teeth from circles,
// polygons and bumps), the teeth's mid-depth crossings, tooth 0 and the axis refined from the tip
// and root circles. Not the flank fits (gear_recognition_flanks.cpp).
#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <complex>
#include <sstream>

#include "geometry/gear_recognition_detail.hpp"

namespace gearsim::recognition_detail {
namespace {

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

}  // namespace

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
    why << "not " << best << "-fold symmetric (rms difference between neighbouring pitches " << lt.residual_m * 1e6 << " um, "
        << lt.residual_m / depth * 100 << " % of the depth)";
  else if (depth < kMinDepthToPitch * pitch_arc)
    why << "a " << best << "-sided polygon (depth " << depth / pitch_arc << " of the pitch), not teeth";
  else
    lt.teeth = best;
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

}  // namespace gearsim::recognition_detail
