#include "physics/tooth_contact.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <map>
#include <numbers>
#include <tuple>

namespace gearsim::physics {
namespace {

using Eigen::Vector2d;

// Golden-section steps refining the deepest point between two flank samples: the bracket
// shrinks by 0.618^20 ≈ 7e-5 of two sample spacings (≈ 5 nm at 64 samples over 2.25 mm).
constexpr int kRefineIterations = 20;

// Gap below which a flank's coarse maximum is refined, m. Normally 5 µm: the parabola between
// samples 140 µm apart (16 samples over a 2.25 mm module-1 tooth) rises at most ~1.2 µm at the
// sun–planet curvature; 5 µm also covers module-2 teeth with 16 samples.
constexpr double kRefineWithin_m = 5e-6;

struct Frame {
  const FlankTable& table;
  PlanarPose pose;
  Vector2d to_world(const Vector2d& p) const { return pose.centre_m + Eigen::Rotation2Dd(pose.angle_rad) * p; }
  Vector2d to_local(const Vector2d& w) const { return Eigen::Rotation2Dd(-pose.angle_rad) * (w - pose.centre_m); }
  Vector2d dir_to_world(const Vector2d& d) const { return Eigen::Rotation2Dd(pose.angle_rad) * d; }
};

// Could tooth k of `x` reach the toothed annulus of `y`? Bounding circle of the tooth against
// the annulus [r_min, r_max] of y (or y's whole disc beyond it on its body side).
bool tooth_near(const Frame& x, int k, const Frame& y) {
  const double rmid = 0.5 * (x.table.r_min_m() + x.table.r_max_m());
  const double half = 0.5 * (x.table.r_max_m() - x.table.r_min_m());
  const double wide = x.table.r_max_m() * x.table.pitch_angle_rad() * 0.5;
  const double radius = std::sqrt(half * half + wide * wide);
  const double a = x.table.tooth_angle_rad(k);
  const Vector2d c = x.to_world(rmid * Vector2d(std::cos(a), std::sin(a)));
  const double d = (c - y.pose.centre_m).norm();
  return d - radius < y.table.r_max_m() && d + radius > y.table.r_min_m();
}

struct Hit {
  double depth = -1e300;
  Vector2d point, normal_into_x;  // world: the probed point and the surface normal of y there
  int tooth_y = -1;
  Flank flank_y = Flank::Ccw;
};

// Depth of x's flank point at radius r inside y, in world terms.
Hit probe_at(const Frame& x, int k, Flank f, double r, const Frame& y) {
  Hit h;
  const Vector2d w = x.to_world(x.table.flank_point(k, f, r));
  const FlankTable::Probe p = y.table.probe(y.to_local(w));
  if (!p.inside && !p.has_flank) return h;  // far from y's teeth: no gap to measure
  h.depth = p.depth_m;
  h.point = w;
  h.normal_into_x = y.dir_to_world(p.normal);
  h.tooth_y = p.tooth;
  h.flank_y = p.flank;
  return h;
}

// The deepest point of one flank of x's tooth k inside y: sampled, then refined by a parabola
// through the best sample and its neighbours.
Hit deepest_on_flank(const Frame& x, int k, Flank f, const Frame& y, int samples) {
  const double r0 = x.table.r_min_m(), r1 = x.table.r_max_m();
  const double step = (r1 - r0) / (samples - 1);
  std::vector<double> depth(samples, -1e300);
  Hit best;
  int best_i = -1;
  for (int i = 0; i < samples; ++i) {
    const double r = r0 + i * step;
    if (std::isnan(x.table.flank_angle(k, f, r))) continue;
    const Hit h = probe_at(x, k, f, r, y);
    depth[i] = h.depth;
    if (h.depth > best.depth) {
      best = h;
      best_i = i;
    }
  }
  // Refine only where contact is possible: between samples the depth can exceed the best
  // sample by at most κ·(spacing/2)²/2 (κ: relative curvature of the flanks).
  if (best_i < 0 || best.depth < -kRefineWithin_m) return best;
  // Golden-section search for the maximum between the best sample's neighbours: the depth is
  // flat at its maximum, but where it sits along the flank fixes the contact point and normal.
  double lo = r0 + std::max(best_i - 1, 0) * step, hi = r0 + std::min(best_i + 1, samples - 1) * step;
  constexpr double kGolden = 0.6180339887498949;
  auto depth_at = [&](double r) {
    return std::isnan(x.table.flank_angle(k, f, r)) ? -1e300 : probe_at(x, k, f, r, y).depth;
  };
  double c = hi - kGolden * (hi - lo), d = lo + kGolden * (hi - lo);
  double fc = depth_at(c), fd = depth_at(d);
  for (int it = 0; it < kRefineIterations; ++it) {
    if (fc > fd) {
      hi = d, d = c, fd = fc;
      c = hi - kGolden * (hi - lo), fc = depth_at(c);
    } else {
      lo = c, c = d, fc = fd;
      d = lo + kGolden * (hi - lo), fd = depth_at(d);
    }
  }
  const double r_best = fc > fd ? c : d;
  if (std::isnan(x.table.flank_angle(k, f, r_best))) return best;
  const Hit refined = probe_at(x, k, f, r_best, y);
  return refined.depth >= best.depth ? refined : best;
}

}  // namespace

std::vector<ToothContact> find_tooth_contacts(const FlankTable& ta, const PlanarPose& pa, const FlankTable& tb,
                                              const PlanarPose& pb, const ToothContactOptions& o) {
  const Frame a{ta, pa}, b{tb, pb};
  // Keyed by (tooth_a, tooth_b, flank of a): the deepest of both probing directions.
  std::map<std::tuple<int, int, int>, ToothContact> best;
  auto keep = [&](int tooth_a, int tooth_b, Flank flank_a, const Hit& h, bool x_is_a) {
    if (h.depth <= 0) return;
    ToothContact c;
    c.tooth_a = tooth_a;
    c.tooth_b = tooth_b;
    c.flank_a = flank_a;
    c.depth_m = h.depth;
    // h.normal_into_x is the outward normal of the probed gear y at the point; the contact
    // normal on b points from b toward a.
    c.normal_on_b = x_is_a ? h.normal_into_x : Vector2d(-h.normal_into_x);
    // The probed point lies on x's surface, y's surface lies a depth further along y's outward
    // normal: the overlap's mid-point is half-way.
    c.point_m = h.point + 0.5 * h.depth * h.normal_into_x;
    auto key = std::make_tuple(tooth_a, tooth_b, static_cast<int>(flank_a));
    auto it = best.find(key);
    if (it == best.end() || it->second.depth_m < c.depth_m) best[key] = c;
  };
  for (int pass = 0; pass < 2; ++pass) {
    const Frame& x = pass == 0 ? a : b;
    const Frame& y = pass == 0 ? b : a;
    for (int k = 0; k < x.table.teeth(); ++k) {
      if (!tooth_near(x, k, y)) continue;
      for (Flank f : {Flank::Ccw, Flank::Cw}) {
        const Hit h = deepest_on_flank(x, k, f, y, o.flank_samples);
        if (h.tooth_y < 0) continue;
        // Name the contact by a's tooth and the flank of a that is touched.
        if (pass == 0) keep(k, h.tooth_y, f, h, true);
        else keep(h.tooth_y, k, h.flank_y, h, false);
      }
    }
  }
  std::vector<ToothContact> out;
  for (const auto& [key, c] : best) out.push_back(c);
  return out;
}

}  // namespace gearsim::physics
