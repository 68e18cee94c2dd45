// FlankTable's probes: where a point lies against the teeth. probe() measures exactly (the foot of
// the normal on the flank) and is what a contact reports; probe_depth() answers to first order
// with no trigonometry, for searching. Both choose the same tooth and flank.
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "contact/fast_angle.hpp"
#include "contact/flank_table.hpp"
#include "contact/integer_round.hpp"
#include "geometry/constants.hpp"

namespace gearsim::contact {
namespace {

using gearsim::constants::kNaN;

}  // namespace

void FlankTable::build_probe_knots() {
  const std::size_t n = static_cast<std::size_t>(samples_);
  knots_.assign(tooth_of_row_.size() * n, {{{kNaN, kNaN, kNaN}, {kNaN, kNaN, kNaN}}});
  for (std::size_t row = 0; row < tooth_of_row_.size(); ++row)
    for (Flank f : {Flank::Ccw, Flank::Cw})
      for (std::size_t i = 0; i < n; ++i) {
        const double r = r_min_ + static_cast<double>(i) * dr_;
        double slope = 0;
        const double a = sample(f == Flank::Ccw ? ccw_ : cw_, tooth_of_row_[row], r, &slope);
        if (std::isnan(a)) continue;
        knots_[row * n + i].side[f == Flank::Cw] = {std::cos(a), std::sin(a), 1 / std::sqrt(1 + r * r * slope * slope)};
      }
  tooth_axis_.resize(static_cast<std::size_t>(layout_.teeth));
  for (int t = 0; t < layout_.teeth; ++t)
    tooth_axis_[static_cast<std::size_t>(t)] = {std::cos(tooth_angle_rad(t)), std::sin(tooth_angle_rad(t))};
  pitch_axis_ = {std::cos(pitch_), std::sin(pitch_)};
  tan_half_pitch_ = std::tan(0.5 * pitch_);
  build_rise_bands();
  build_convexity_bands();
}

std::size_t FlankTable::band_levels(int bands, LevelStarts& start) {
  start.fill(0);
  std::size_t length = 0;
  for (int run = 1, l = 0; run <= bands; run *= 2, ++l) {
    start[static_cast<std::size_t>(l)] = length;
    length += static_cast<std::size_t>(bands - run + 1);
  }
  return length;
}

void FlankTable::build_rise_bands() {
  const int n = samples_;
  const int intervals = n - 1, bands = (intervals + kRiseBand - 1) / kRiseBand;
  std::vector<FirstOrderRise> bands_max(static_cast<std::size_t>(bands), FirstOrderRise{0, 0, 0, 0});
  const std::size_t rows = tooth_of_row_.size();
  auto worst = [](double& into, double v) { into = std::isnan(v) || !(v < kInfinity) ? kInfinity : std::max(into, v); };
  for (int i = 0; i < intervals; ++i) {
    FirstOrderRise& band = bands_max[static_cast<std::size_t>(i / kRiseBand)];
    const double r_hi = r_min_ + (i + 1) * dr_;
    double c_min = kInfinity, c_max = 0;
    for (std::size_t row = 0; row < rows; ++row)
      for (int side = 0; side < 2; ++side) {
        const Knot& k0 = knots_[row * static_cast<std::size_t>(n) + static_cast<std::size_t>(i)].side[side];
        const Knot& k1 = knots_[row * static_cast<std::size_t>(n) + static_cast<std::size_t>(i) + 1].side[side];
        const double c_lo = std::min(k0.cos_psi, k1.cos_psi), c_up = std::max(k0.cos_psi, k1.cos_psi);
        const double v_up = std::max(std::hypot(k0.cos_a, k0.sin_a), std::hypot(k1.cos_a, k1.sin_a));
        const double dv = std::hypot(k1.cos_a - k0.cos_a, k1.sin_a - k0.sin_a) / dr_;
        // NaN knots (no material) and c → 0 make the band unbounded.
        worst(band.slope, c_up * (v_up + r_hi * dv));
        worst(band.side, v_up + r_hi * dv);
        worst(band.growth, c_lo > 0 ? std::abs(k1.cos_psi - k0.cos_psi) / (dr_ * c_lo) : kInfinity);
        c_min = std::isnan(c_lo) ? 0 : std::min(c_min, c_lo);
        c_max = std::isnan(c_up) ? kInfinity : std::max(c_max, c_up);
      }
    worst(band.jump, c_min > 0 ? (c_max - c_min) / c_min : kInfinity);
  }
  rise_flat_.assign(band_levels(bands, rise_level_start_), FirstOrderRise{});
  std::copy(bands_max.begin(), bands_max.end(), rise_flat_.begin());
  fill_band_runs(rise_flat_.data(), bands, rise_level_start_, larger_rise);
}

int FlankTable::nearest_tooth(const Eigen::Vector2d& p) const {
  return wrap_tooth(static_cast<int>(round_to_even((rough_atan2(p.y(), p.x()) - layout_.tooth0_angle_rad) * inv_pitch_)));
}

Eigen::Vector2d FlankTable::in_tooth_frame(const Eigen::Vector2d& p, int k) const {
  const Eigen::Vector2d& axis = tooth_axis_[static_cast<std::size_t>(k)];
  return {axis.x() * p.x() + axis.y() * p.y(), axis.x() * p.y() - axis.y() * p.x()};
}

// Inline: every call is in this file (first_order_depth() and the probes, ≈ 54 per paper step).
inline int FlankTable::nearest_tooth_from(const Eigen::Vector2d& p, int k, Eigen::Vector2d* q) const {
  // Within half a pitch of tooth k's centre line: |q_y| ≤ tan(π/z)·q_x in the tooth's frame. A
  // point on a tooth is far inside that cone; one near the cone's edge lies mid-way across a
  // tooth space, where either bounding tooth gives the same depth (probe_depth() compares the
  // space's two flanks).
  for (int step = 0; step < 3; ++step) {
    *q = in_tooth_frame(p, k);
    if (!(q->x() > 0)) break;
    if (std::abs(q->y()) <= tan_half_pitch_ * q->x()) return k;
    k = wrap_tooth(k + (q->y() > 0 ? 1 : -1));
  }
  k = nearest_tooth(p);
  *q = in_tooth_frame(p, k);
  return k;
}

FlankTable::Probe FlankTable::probe_depth(const Eigen::Vector2d& p, int tooth_hint) const {
  Probe out;
  const double r2 = p.squaredNorm();
  // Beyond the teeth: free, or solid body (below an external root, outside an internal root).
  if (internal_ ? r2 < r_min_ * r_min_ : r2 > r_max_ * r_max_) return out;
  const double r = std::sqrt(r2);
  Eigen::Vector2d q;
  const int k = tooth_hint < 0 ? nearest_tooth(p) : nearest_tooth_from(p, tooth_hint, &q);
  out.tooth = k;
  if (internal_ ? r > r_max_ : r < r_min_) {
    out.inside = true;
    out.depth_m = internal_ ? r - r_max_ : r_min_ - r;
    out.normal = (internal_ ? -1.0 : 1.0) * p / r;
    return out;
  }
  const FirstOrder fo = first_order(tooth_hint < 0 ? in_tooth_frame(p, k) : q, r, k);
  if (!fo.has_flank) return out;
  out.inside = fo.inside;
  out.has_flank = true;
  out.tooth = fo.tooth;
  out.flank = fo.flank;
  out.depth_m = fo.depth_m;
  return out;
}

FlankTable::Facing FlankTable::face(const Eigen::Vector2d& p, int tooth_hint) const {
  Facing out;
  const double r2 = p.squaredNorm();
  if (internal_ ? r2 < r_min_ * r_min_ : r2 > r_max_ * r_max_) return out;
  const double r = std::sqrt(r2);
  if (internal_ ? r > r_max_ : r < r_min_) return out;
  Eigen::Vector2d q;
  const int k = nearest_tooth_from(p, tooth_hint, &q);
  double margin = -1;
  const FirstOrder fo = first_order(q, r, k, &margin);
  if (!fo.has_flank) return out;
  out.has_flank = true;
  out.tooth = fo.tooth;
  out.flank = fo.flank;
  out.margin_m = margin;
  return out;
}

double FlankTable::first_order_depth(const Eigen::Vector2d& p, int& tooth_hint) const {
  const double r2 = p.squaredNorm();
  if (internal_ ? r2 < r_min_ * r_min_ : r2 > r_max_ * r_max_) return kNoDepth;
  const double r = std::sqrt(r2);
  if (internal_ ? r > r_max_ : r < r_min_) return internal_ ? r - r_max_ : r_min_ - r;
  Eigen::Vector2d q;
  int k;
  if (tooth_hint < 0) {
    k = nearest_tooth(p);
    q = in_tooth_frame(p, k);
  } else {
    k = nearest_tooth_from(p, tooth_hint, &q);
  }
  const FirstOrder fo = first_order(q, r, k);
  if (!fo.has_flank) return kNoDepth;
  tooth_hint = fo.tooth;
  return fo.depth_m;
}

FlankTable::FirstOrder FlankTable::first_order(const Eigen::Vector2d& q, double r, int k, double* margin) const {
  FirstOrder out;
  // q: the point in tooth k's frame (its centre line on +x); the flanks' knots around r.
  const double x = (r - r_min_) * inv_dr_;
  const int i = std::clamp(static_cast<int>(x), 0, samples_ - 2);
  const double f = x - i;
  // r·sin(rel − a) of a point at angle rel against a flank at angle a (tooth frame); cos ψ only
  // for the flank chosen.
  auto side = [&](const KnotPair* kn, int flank, const Eigen::Vector2d& qq) {
    const Knot &k0 = kn[0].side[flank], &k1 = kn[1].side[flank];
    const double ca = k0.cos_a + f * (k1.cos_a - k0.cos_a);
    const double sa = k0.sin_a + f * (k1.sin_a - k0.sin_a);
    return qq.y() * ca - qq.x() * sa;
  };
  const KnotPair* own = knots(k) + i;
  const double ccw = side(own, 0, q), cw = side(own, 1, q);
  if (std::isnan(ccw) || std::isnan(cw)) return out;
  out.tooth = k;
  out.inside = cw > 0 && ccw < 0;
  // Inside: the nearer flank of this tooth. In a tooth space: the facing flank of this tooth or
  // of the neighbour, whichever is nearer (sin is monotone over these angles); the depth then
  // comes out negative (a gap), so a prober sees the approach, not only overlap.
  bool to_ccw = out.inside ? -ccw < cw : ccw >= 0;
  double chosen = to_ccw ? ccw : cw;
  const KnotPair* chosen_knots = own;
  if (!out.inside || margin) {
    // The neighbour across the tooth space on the chosen side, and its flank facing it.
    const int next = wrap_tooth(k + (to_ccw ? 1 : -1));
    const double sp = to_ccw ? pitch_axis_.y() : -pitch_axis_.y();
    const Eigen::Vector2d qn(pitch_axis_.x() * q.x() + sp * q.y(), pitch_axis_.x() * q.y() - sp * q.x());
    const KnotPair* next_knots = knots(next) + i;
    const double facing = side(next_knots, to_ccw ? 1 : 0, qn);
    const double own_gap = to_ccw ? ccw : -cw, next_gap = to_ccw ? -facing : facing;
    // face(): the least offset of the candidates not chosen, less the chosen one's.
    if (margin) {
      const double c = std::abs(ccw), w = std::abs(cw), n = std::abs(facing);
      const bool to_next = !out.inside && !std::isnan(facing) && next_gap < own_gap;
      *margin = std::isnan(facing) ? -1.0 : to_next ? std::min(c, w) - n : to_ccw ? std::min(w, n) - c : std::min(c, n) - w;
    }
    if (!out.inside && !std::isnan(facing) && next_gap < own_gap) {
      out.tooth = next;
      to_ccw = !to_ccw;
      chosen = facing;
      chosen_knots = next_knots;
    }
  }
  const Knot &k0 = chosen_knots[0].side[to_ccw ? 0 : 1], &k1 = chosen_knots[1].side[to_ccw ? 0 : 1];
  const double cos_psi = k0.cos_psi + f * (k1.cos_psi - k0.cos_psi);
  out.flank = to_ccw ? Flank::Ccw : Flank::Cw;
  out.depth_m = (to_ccw ? -chosen : chosen) * cos_psi;
  out.has_flank = true;
  return out;
}

FlankTable::Probe FlankTable::probe(const Eigen::Vector2d& p) const {
  // Which tooth and flank: as probe_depth() chooses them (the facing flank of the nearer tooth;
  // in a tooth space, the nearer of its two flanks).
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

}  // namespace gearsim::contact
