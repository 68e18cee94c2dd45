#include "physics/flank_table.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "geometry/errors.hpp"

namespace gearsim::physics {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Radial margin kept inside the loop's extent, as a share of it: the root and tip arcs are
// chords whose sagitta dips below the nominal circle; 1e-4 of a 2 mm tooth is 0.2 µm.
constexpr double kEdgeShare = 1e-4;

// Half-width, in samples, of the central difference for dθ/dr (see sample()).
constexpr int kSlopeSpan = 2;

// Teeth whose flanks differ by less than this everywhere share their table rows, m (as an arc at
// the tip). Normally 0.1 nm: 5000 times below the 0.5 µm outline accuracy, far above the 1e-14 m
// rounding between a generated gear's rotated copies of one tooth.
constexpr double kSharedToothTolerance_m = 1e-10;

// Consecutive flank vertices closer in radius than this are one knot, m: float32 noise of an
// imported tip or root arc (~1e-9 m at gear scale) must not pass for a flank.
constexpr double kKnotSpacing_m = 1e-8;

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
  // its vertices as knots of a cubic in r, then sampled. Per tooth sector, the Cw flank is the
  // longest run of vertices whose radius strictly increases (walking the loop counter-clockwise)
  // and the Ccw flank the longest strictly decreasing run, for an external gear; the other way
  // round for an internal one, whose teeth point inward.
  std::vector<Eigen::Vector2d> pts = loop.points;
  if (signed_area(loop) < 0) std::reverse(pts.begin(), pts.end());
  const std::size_t n = pts.size();
  std::vector<int> tooth_of(n);
  std::vector<double> rel_of(n), r_of(n);
  for (std::size_t q = 0; q < n; ++q) {
    const double phi = std::atan2(pts[q].y(), pts[q].x()) - layout.tooth0_angle_rad;
    const long k = std::lround(phi / pitch_);
    tooth_of[q] = static_cast<int>(((k % layout.teeth) + layout.teeth) % layout.teeth);
    rel_of[q] = std::remainder(phi - static_cast<double>(k) * pitch_, 2 * kPi);
    r_of[q] = pts[q].norm();
  }
  // Longest strictly monotone runs per (tooth, side), as index ranges into the loop.
  struct Run { std::size_t start = 0, length = 0; };
  std::vector<Run> best(static_cast<std::size_t>(layout.teeth) * 2);
  for (int dir : {+1, -1}) {
    std::size_t q = 0;
    while (q < n) {
      std::size_t len = 1;
      while (len < n && tooth_of[(q + len) % n] == tooth_of[q] &&
             dir * (r_of[(q + len) % n] - r_of[(q + len - 1) % n]) > kKnotSpacing_m)
        ++len;
      // Ascending r along the loop: Cw side of an external tooth, Ccw side of an internal one.
      const bool cw_side = (dir > 0) != internal;
      Run& b = best[static_cast<std::size_t>(tooth_of[q]) * 2 + (cw_side ? 1 : 0)];
      if (len > b.length) b = {q, len};
      q += std::max<std::size_t>(len - 1, 1);
    }
  }
  for (int t = 0; t < layout.teeth; ++t)
    for (int side = 0; side < 2; ++side) {
      const Run& run = best[static_cast<std::size_t>(t) * 2 + side];
      if (run.length < 4)
        throw InputError("flank table: tooth " + std::to_string(t) + " has no flank of at least 4 vertices whose "
                         "radius grows monotonically: the toothed outline is not star-shaped about the axis, "
                         "or the tooth layout does not match it");
      std::vector<double> kr, ka;
      for (std::size_t m = 0; m < run.length; ++m) {
        const std::size_t q = (run.start + m) % n;
        kr.push_back(r_of[q]);
        ka.push_back(rel_of[q]);
      }
      if (kr.front() > kr.back()) {
        std::reverse(kr.begin(), kr.end());
        std::reverse(ka.begin(), ka.end());
      }
      std::vector<double>& table = side == 0 ? ccw_ : cw_;
      for (int i = 0; i < samples; ++i) {
        const double r = r_min_ + i * dr_;
        if (r < kr.front() || r > kr.back()) continue;  // no material of this flank here
        // Cubic through the four knots around r (Lagrange, non-uniform).
        std::size_t j = static_cast<std::size_t>(std::upper_bound(kr.begin(), kr.end(), r) - kr.begin());
        j = std::clamp<std::size_t>(j, 2, kr.size() - 2) - 2;
        double value = 0;
        for (std::size_t a = j; a < j + 4; ++a) {
          double w = 1;
          for (std::size_t b = j; b < j + 4; ++b)
            if (b != a) w *= (r - kr[b]) / (kr[a] - kr[b]);
          value += w * ka[a];
        }
        table[static_cast<std::size_t>(t) * samples + i] = value;
      }
    }
  share_identical_teeth();
  probe_points_.resize(static_cast<std::size_t>(layout.teeth) * 2 * kProbeRadii);
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
        probe_points_[(static_cast<std::size_t>(t) * 2 + (f == Flank::Cw)) * kProbeRadii + i] =
            std::isnan(flank_angle(t, f, r)) ? Eigen::Vector2d(kNaN, kNaN) : flank_point(t, f, r);
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
  int i = static_cast<int>(std::floor(x));
  i = std::clamp(i, 0, samples_ - 2);
  const double f = x - i;
  const double* row = table.data() + static_cast<std::size_t>(row_of_[static_cast<std::size_t>(tooth)]) * samples_;
  if (slope) {
    // Central difference over ±kSlopeSpan samples of the cubic knots' interpolant; where the
    // span leaves the tooth, the one interval.
    const int lo = std::max(i - kSlopeSpan, 0), hi = std::min(i + 1 + kSlopeSpan, samples_ - 1);
    *slope = (std::isnan(row[lo]) || std::isnan(row[hi])) ? (row[i + 1] - row[i]) * inv_dr_
                                                          : (row[hi] - row[lo]) * inv_dr_ / (hi - lo);
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

Eigen::Vector2d FlankTable::flank_point(int tooth, Flank flank, double r) const {
  const double a = tooth_angle_rad(tooth) + flank_angle(tooth, flank, r);
  return r * Eigen::Vector2d(std::cos(a), std::sin(a));
}

struct FlankTable::Located {
  enum Kind { Free, Body, NoMaterial, Teeth } kind = Free;
  double r = 0;
  int tooth = -1;
  Flank flank = Flank::Ccw;
  bool inside = false;
  double rel = 0;  // angle from the chosen tooth's centre line, rad
};

FlankTable::Located FlankTable::locate(const Eigen::Vector2d& p) const {
  Located l;
  l.r = p.norm();
  // Beyond the teeth: free (no atan2 needed), or solid body (below an external root, outside an
  // internal root).
  if (internal_ ? l.r < r_min_ : l.r > r_max_) return l;
  const double phi = std::atan2(p.y(), p.x()) - layout_.tooth0_angle_rad;
  const double k = std::nearbyint(phi * inv_pitch_);
  l.tooth = wrap_tooth(static_cast<int>(k));
  double rel = phi - k * pitch_;  // within half a pitch of the tooth
  if (internal_ ? l.r > r_max_ : l.r < r_min_) {
    l.kind = Located::Body;
    l.inside = true;
    return l;
  }
  const double a_ccw = sample(ccw_, l.tooth, l.r, nullptr);
  const double a_cw = sample(cw_, l.tooth, l.r, nullptr);
  if (std::isnan(a_ccw) || std::isnan(a_cw)) {
    l.kind = Located::NoMaterial;
    return l;
  }
  l.kind = Located::Teeth;
  l.inside = rel > a_cw && rel < a_ccw;
  // Inside: the nearer flank of this tooth. Outside (in a tooth space): the flank of this tooth
  // that faces the point, or the facing flank of the neighbour if that one is nearer in angle;
  // the depth then comes out negative (a gap), so a prober sees the approach, not only overlap.
  bool to_ccw = l.inside ? a_ccw - rel < rel - a_cw : rel >= a_ccw;
  if (!l.inside) {
    const int next = wrap_tooth(l.tooth + (to_ccw ? 1 : -1));
    const double neighbour = sample(to_ccw ? cw_ : ccw_, next, l.r, nullptr) + (to_ccw ? pitch_ : -pitch_);
    const double own_gap = to_ccw ? rel - a_ccw : a_cw - rel;
    const double next_gap = to_ccw ? neighbour - rel : rel - neighbour;
    if (!std::isnan(neighbour) && next_gap < own_gap) {
      l.tooth = next;
      rel += to_ccw ? -pitch_ : pitch_;
      to_ccw = !to_ccw;
    }
  }
  l.flank = to_ccw ? Flank::Ccw : Flank::Cw;
  l.rel = rel;
  return l;
}

FlankTable::Probe FlankTable::probe_depth(const Eigen::Vector2d& p) const {
  const Located l = locate(p);
  Probe out;
  out.tooth = l.tooth;
  out.flank = l.flank;
  out.inside = l.inside;
  if (l.kind == Located::Body) {
    out.depth_m = internal_ ? l.r - r_max_ : r_min_ - l.r;
    out.normal = (internal_ ? -1.0 : 1.0) * p / l.r;
  }
  if (l.kind != Located::Teeth) return out;
  double slope = 0;
  const double a = sample(l.flank == Flank::Ccw ? ccw_ : cw_, l.tooth, l.r, &slope);
  const double offset = l.flank == Flank::Ccw ? a - l.rel : l.rel - a;  // > 0 inside
  out.depth_m = l.r * offset / std::sqrt(1 + l.r * l.r * slope * slope);
  out.has_flank = true;
  return out;
}

FlankTable::Probe FlankTable::probe(const Eigen::Vector2d& p) const {
  Probe out = probe_depth(p);
  if (!out.has_flank) return out;
  // Foot of the normal from p on the flank: start at the flank point of the same radius, slide
  // along its tangent to the projection of p, and take the flank point at that radius. Two
  // passes leave an error third-order in the depth (the first pass alone biases where along the
  // flank the deepest point appears by µm, which tilts the normal).
  double rf = p.norm();
  FlankFrame ff = flank_frame(out.tooth, out.flank, rf);
  for (int pass = 0; pass < 2; ++pass) {
    const Eigen::Vector2d foot = ff.point + (p - ff.point).dot(ff.tangent) * ff.tangent;
    const double r_next = foot.norm();
    if (r_next <= r_min_ || r_next >= r_max_) break;
    const FlankFrame next = flank_frame(out.tooth, out.flank, r_next);
    if (std::isnan(next.point.x())) break;
    ff = next;
  }
  out.depth_m = (ff.point - p).dot(ff.normal);
  out.normal = ff.normal;
  return out;
}

FlankTable::FlankFrame FlankTable::flank_frame(int tooth, Flank flank, double r) const {
  double slope = 0;
  const double rel = sample(flank == Flank::Ccw ? ccw_ : cw_, tooth, r, &slope);
  const double a = tooth_angle_rad(tooth) + rel;
  const Eigen::Vector2d radial(std::cos(a), std::sin(a)), tangential(-std::sin(a), std::cos(a));
  FlankFrame f;
  f.point = r * radial;
  // d(point)/dr = radial + r·θ'·tangential; the outward normal turns it a quarter turn toward
  // increasing angle for a Ccw flank, decreasing for a Cw flank.
  f.tangent = (radial + r * slope * tangential).normalized();
  const Eigen::Vector2d n(-f.tangent.y(), f.tangent.x());
  f.normal = flank == Flank::Ccw ? n : Eigen::Vector2d(-n);
  return f;
}

}  // namespace gearsim::physics
