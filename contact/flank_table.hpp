// FlankTable: the flanks of every tooth of a spur gear as polar functions θ(r), sampled densely
// in radius, built from the gear's toothed outline and tooth layout. It answers "is this point
// (in the gear's frame) inside tooth material, and how deep" in O(1), to the outline's accuracy:
// the basis of tooth contact. Works for external and internal gears, generated or imported, as
// long as the toothed loop is star-shaped about the axis (each circle crosses each flank once).
// Not a collision shape for Bullet.
#pragma once

#include <Eigen/Core>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <utility>
#include <vector>

#include "contact/integer_round.hpp"
#include "geometry/convex_decomposition.hpp"
#include "geometry/gear_spec.hpp"
#include "geometry/outline.hpp"

namespace gearsim::contact {

class FlankTable {
 public:
  // `loop`: the toothed loop (either orientation), gear frame, m. Throws InputError when the loop
  // is not star-shaped per tooth sector.
  FlankTable(const Polygon2& loop, const ToothLayout& layout, bool internal, int samples);

  int teeth() const { return layout_.teeth; }
  // How far the table strays from the polyline of its loop beyond the sagitta of a smooth curve
  // through the loop's vertices (flank_knots.hpp), and where: a table built from a mesh it does
  // not describe (a wrong tooth layout, a flank cut by noise) shows here.
  struct Departure {
    double departure_m = 0;
    int tooth = -1;
    Flank flank = Flank::Ccw;
    double r_m = 0;
  };
  const Departure& departure() const { return departure_; }
  // How well each vertex of the loop's flanks is predicted by its neighbours, m
  // (knot_resolution_m in flank_knots.hpp): coarse facets or coordinate noise.
  double knot_resolution_m() const { return knot_resolution_m_; }
  bool internal() const { return internal_; }
  // True when both tables describe the same flanks (same layout, radii and samples, bit for bit:
  // the samples without material, NaN, compare equal to each other).
  bool same_as(const FlankTable& o) const {
    auto same_bits = [](const std::vector<double>& u, const std::vector<double>& v) {
      return u.size() == v.size() && (u.empty() || std::memcmp(u.data(), v.data(), u.size() * sizeof(double)) == 0);
    };
    return layout_.teeth == o.layout_.teeth && layout_.tooth0_angle_rad == o.layout_.tooth0_angle_rad && internal_ == o.internal_ &&
           r_min_ == o.r_min_ && r_max_ == o.r_max_ && samples_ == o.samples_ && row_of_ == o.row_of_ && same_bits(ccw_, o.ccw_) &&
           same_bits(cw_, o.cw_);
  }
  // Distinct tooth shapes the table holds (identical teeth share one), for memory accounting.
  int distinct_teeth() const { return static_cast<int>(ccw_.size()) / samples_; }
  double pitch_angle_rad() const { return pitch_; }
  double tooth_angle_rad(int tooth) const { return layout_.tooth0_angle_rad + tooth * pitch_; }
  // Radial extent of the teeth: root to tip (external) or tip to root (internal), m.
  double r_min_m() const { return r_min_; }
  double r_max_m() const { return r_max_; }

  // Angle of a flank relative to its tooth's centre line at radius r (rad; Cw < 0 < Ccw), and
  // dθ/dr. NaN where the tooth has no material at that radius (above an external tip, below an
  // internal one). r must lie in [r_min, r_max].
  double flank_angle(int tooth, Flank flank, double r) const;
  double flank_slope(int tooth, Flank flank, double r) const;

  // Where a point in the gear frame lies against the material.
  struct Probe {
    bool inside = false;  // in tooth material (or the solid body beyond the teeth)
    bool has_flank = false;  // depth_m and normal refer to a flank (also for a point in a gap)
    int tooth = -1;  // nearest tooth
    Flank flank = Flank::Ccw;  // nearest flank
    double depth_m = 0;  // distance to that flank along its normal (> 0 inside, < 0 in a gap)
    Eigen::Vector2d normal = Eigen::Vector2d::Zero();  // outward flank normal, gear frame
  };
  Probe probe(const Eigen::Vector2d& p) const;
  // The same answer without the normal and with the depth to first order: the angular offset
  // from the flank at the point's own radius times r·cos ψ (ψ: the flank's angle to the radial).
  // Its error is about depth²·curvature (1e-9 m at 1 µm, 5 µm at a 100 µm gap): for searching
  // the deepest point, three times cheaper than probe() (no trigonometry after one atan2).
  // `tooth_hint` ≥ 0: a tooth near the point, from which the tooth it lies on (or one bounding
  // its tooth space) is found by stepping instead of from its angle (as first_order_depth()).
  Probe probe_depth(const Eigen::Vector2d& p, int tooth_hint = -1) const;
  // The flank probe_depth(p, tooth_hint) chooses (tooth, flank; none: has_flank false) and by how
  // much: the least unscaled offset |q × v| of the other candidate flanks (the tooth's other
  // flank, the neighbour's facing one) less the chosen flank's, m (−1 where one is not measured).
  // A point moved by δ, along a path over radii where first_order_rise().side ≤ L, still
  // faces the same flank while 2·L·δ stays below that margin: each offset moves by at most L·δ,
  // and the choice is the candidate nearest by offset (crossing a flank makes it the nearest).
  struct Facing {
    bool has_flank = false;
    int tooth = -1;
    Flank flank = Flank::Ccw;
    double margin_m = -1;
  };
  Facing face(const Eigen::Vector2d& p, int tooth_hint) const;
  // probe_depth()'s depth alone, kNoDepth where it measures nothing (free space, no material).
  // `tooth_hint`, a tooth near the point or −1, replaces the angle search and is set to the tooth
  // found: for points probed in sequence along one flank. Both choose the tooth the point lies
  // on, or one of the two that bound the tooth space it lies in, and so the same depth.
  static constexpr double kNoDepth = -1e300;
  double first_order_depth(const Eigen::Vector2d& p, int& tooth_hint) const;

  // How fast first_order_depth() D can change as a point moves, over radii [r_lo, r_hi] within
  // the teeth: the bounds a search that skips a flank until its measured gap may have closed
  // rests on (CoherentToothSearch, coherent_contact.hpp). Against one flank, D = c·(q × v)
  // with v (the flank's direction) and c (cos ψ) linear in r between knots, so
  //   |∇D| ≤ c·|v| + c·r·|dv/dr| + |dc/dr|·|D|/c ≤ slope + growth·|D|.
  // In a tooth space D is taken on the nearer of its two flanks by their unscaled gaps g
  // (D = −c_sel·g_sel); the larger of the two flanks' own depths, D̃ = max(−c·g) ≥ D, is
  // continuous there and at most jump·|D| above D (jump = (max c − min c)/min c at the
  // radius). Infinite where a flank has no material (D is not measured there).
  // `side`: the same bound on the unscaled offset q × v alone (|v| + r·|dv/dr|), by which a
  // point's flank is chosen (face(), probe_depth()).
  struct FirstOrderRise {
    double slope = kInfinity, growth = kInfinity, jump = kInfinity, side = kInfinity;  // 1, 1/m, 1, 1
  };
  static constexpr double kInfinity = 1e300;
  [[gnu::always_inline]] FirstOrderRise first_order_rise(double r_lo_m, double r_hi_m) const {
    const double last = samples_ - 2, lo = (r_lo_m - r_min_) * inv_dr_, hi = (r_hi_m - r_min_) * inv_dr_;
    const int b_lo = static_cast<int>(lo <= 0 ? 0 : lo >= last ? last : lo) / kRiseBand;
    const int b_hi = static_cast<int>(hi <= 0 ? 0 : hi >= last ? last : hi) / kRiseBand;
    return band_range(rise_flat_.data(), rise_level_start_, b_lo, b_hi, larger_rise);
  }

  // Points of every flank at `kProbeRadii` evenly spaced radii from r_min to r_max (gear frame,
  // m; NaN where the flank has no material), kept so that probing a flank costs no trigonometry.
  static constexpr int kProbeRadii = 16;
  static_assert(kProbeRadii <= 32, "probe_material() holds one bit per probe radius");
  const Eigen::Vector2d& probe_point(int tooth, Flank flank, int i) const {
    return probe_points_[(static_cast<std::size_t>(tooth) * 2 + (flank == Flank::Cw)) * kProbeRadii + i];
  }
  double probe_radius(int i) const { return r_min_ + i * (r_max_ - r_min_) / (kProbeRadii - 1); }
  // Bit i set where the flank has material at probe radius i (its probe point is not NaN).
  std::uint32_t probe_material(int tooth, Flank flank) const {
    return probe_material_[static_cast<std::size_t>(tooth) * 2 + (flank == Flank::Cw)];
  }
  // Centre of a tooth's radial extent on its centre line (gear frame), m, and the radius of a
  // circle about it that holds the whole tooth.
  const Eigen::Vector2d& tooth_centre(int tooth) const { return tooth_centres_[tooth]; }
  double tooth_bound_radius_m() const { return tooth_bound_; }

  // A point on a flank at radius r (gear frame), m.
  Eigen::Vector2d flank_point(int tooth, Flank flank, double r) const;
  // The same point, false where the flank has no material at r (flank_angle() is NaN there).
  bool flank_point_if_material(int tooth, Flank flank, double r, Eigen::Vector2d* point) const;

  // Point, unit tangent (toward increasing radius) and outward unit normal of a flank at r.
  struct FlankFrame {
    Eigen::Vector2d point, tangent, normal;
  };
  FlankFrame flank_frame(int tooth, Flank flank, double r) const;

  // A flank point at r with its first and second derivatives in r (gear frame), on the smooth
  // (C¹) interpolant of the table: cubic Hermite through the samples with slopes by central
  // differences (one-sided next to a radius without material). Its normal turns continuously
  // along the flank, so a contact on it can be solved by Newton's method (flank_newton_impl.hpp).
  // False where the interval around r lacks material (no jet then).
  struct FlankJet {
    Eigen::Vector2d point, d1, d2;  // m, 1, 1/m
  };
  bool flank_jet(int tooth, Flank flank, double r, FlankJet* jet) const;
  // True when radii r0 and r1 lie in one interval of the samples (one cubic of the interpolant
  // flank_jet() evaluates): a jet at r0 expands the flank to r1 without a jump of its second
  // derivative between them.
  bool same_interval(double r0, double r1) const {
    const double x0 = (r0 - r_min_) * inv_dr_, x1 = (r1 - r_min_) * inv_dr_;
    if (!(std::abs(x0) < kIntegerRoundLimit && std::abs(x1) < kIntegerRoundLimit)) return std::floor(x0) == std::floor(x1);
    return floor_small(x0) == floor_small(x1);
  }
  // The radii of a flank's first and last sample with material (its root and tip ends), m.
  void flank_extent(int tooth, Flank flank, double* r_lo, double* r_hi) const {
    const std::pair<double, double>& e =
        extents_[static_cast<std::size_t>(row_of_[static_cast<std::size_t>(tooth)]) * 2 + (flank == Flank::Cw)];
    *r_lo = e.first;
    *r_hi = e.second;
  }
  // A flank's convexity at a jet: the curvature of the interpolant, 1/m, > 0 where the flank
  // bends away from its outward normal (its centre of curvature inside the material: an external
  // gear's involute), < 0 where it bends toward it (an internal gear's involute, a fillet).
  static double convexity(Flank flank, const FlankJet& jet) {
    const double cross = jet.d1.x() * jet.d2.y() - jet.d1.y() * jet.d2.x(), norm = jet.d1.norm();
    const double turn_left = cross / (norm * norm * norm);  // toward d1 turned by +90°
    return flank == Flank::Ccw ? -turn_left : turn_left;  // the outward normal is d1 turned by +90° on Ccw
  }
  // The least and largest convexity of a flank's interpolant over radii [r_lo, r_hi], 1/m: from
  // bands of kConvexityBand sample intervals, each interval's cubic evaluated at its two ends and
  // two points between (within one cubic the curvature varies smoothly; between cubics it jumps,
  // the interpolant being C¹ only, and both sides of every knot are evaluated). Unbounded
  // ({−kInfinity, kInfinity}) where the range leaves [r_min, r_max] or reaches a radius without
  // material.
  struct ConvexityRange {
    double lo = -kInfinity, hi = kInfinity;
  };
  static constexpr int kConvexityBand = 8;
  ConvexityRange convexity_range(int tooth, Flank flank, double r_lo_m, double r_hi_m) const;
  // The outward unit normal of a flank with derivative d1 (FlankJet::d1) at a point.
  static Eigen::Vector2d outward_normal(Flank flank, const Eigen::Vector2d& d1) {
    const Eigen::Vector2d n = Eigen::Vector2d(-d1.y(), d1.x()).normalized();
    return flank == Flank::Ccw ? n : Eigen::Vector2d(-n);
  }

 private:
  double sample(const std::vector<double>& table, int tooth, double r, double* slope) const;
  // A flank's samples (its shared row), rad.
  const double* row_data(int tooth, Flank flank) const {
    return (flank == Flank::Ccw ? ccw_ : cw_).data() + static_cast<std::size_t>(row_of_[static_cast<std::size_t>(tooth)]) * samples_;
  }
  void build_extents();
  std::vector<std::pair<double, double>> extents_;  // [row * 2 + (flank == Cw)]: flank_extent()
  void share_identical_teeth();
  void build_probe_knots();
  // The probe_depth() path: per shared row, flank and radius sample, the flank direction and
  // cos ψ, so that a probe needs no trigonometry (see flank_probe.cpp).
  struct Knot {
    double cos_a, sin_a;  // direction of the flank point at this radius, tooth frame (NaN: no material)
    double cos_psi;  // cosine of the flank's angle to the radial: 1/√(1 + (r·dθ/dr)²)
  };
  // Both flanks' knots of one radius side by side: a probe reads both at once (one cache line
  // pair instead of two).
  struct KnotPair {
    Knot side[2];  // [0] Ccw, [1] Cw
  };
  const KnotPair* knots(int tooth) const {
    return knots_.data() + static_cast<std::size_t>(row_of_[static_cast<std::size_t>(tooth)]) * samples_;
  }
  // The nearest tooth to a point of the gear frame at radius in the teeth: from a rough atan2,
  // or, given a tooth near it, by stepping to the neighbour while the point lies more than half
  // a pitch from the tooth's centre line (no trigonometry; q: the point in its frame).
  // Unit vector at angle rel from tooth's centre line (gear frame).
  Eigen::Vector2d direction(int tooth, double rel) const;
  int nearest_tooth(const Eigen::Vector2d& p) const;
  int nearest_tooth_from(const Eigen::Vector2d& p, int hint, Eigen::Vector2d* q) const;
  // A point of the gear frame in tooth k's frame (its centre line on +x).
  Eigen::Vector2d in_tooth_frame(const Eigen::Vector2d& p, int k) const;
  // probe_depth()'s measure of a point at radius r within the teeth, against tooth k (its
  // nearest) and the neighbour across the tooth space it may lie in; q: the point in tooth k's
  // frame.
  struct FirstOrder {
    bool inside = false, has_flank = false;
    int tooth = -1;
    Flank flank = Flank::Ccw;
    double depth_m = 0;
  };
  // `margin`: where given, face()'s margin (m, −1 where a candidate is not measured).
  FirstOrder first_order(const Eigen::Vector2d& q, double r, int k, double* margin = nullptr) const;
  // A tooth number taken modulo the tooth count (k within a few turns of the range).
  int wrap_tooth(int k) const {
    while (k < 0) k += layout_.teeth;
    while (k >= layout_.teeth) k -= layout_.teeth;
    return k;
  }

  ToothLayout layout_;
  bool internal_;
  Departure departure_;
  double knot_resolution_m_ = 0;
  double pitch_;
  double r_min_, r_max_, dr_, inv_dr_, inv_pitch_;
  int samples_;
  std::vector<double> ccw_, cw_;  // [row * samples + i], rad relative to the tooth centre
  std::vector<int> row_of_;  // tooth → its row (identical teeth share one)
  std::vector<int> tooth_of_row_;  // a tooth of each row
  std::vector<KnotPair> knots_;  // [row * samples + i]
  // first_order_rise() per band of kRiseBand knot intervals (max over rows and flanks), and over
  // runs of bands: rise_flat_[rise_level_start_[l] + b] over bands b to b + 2^l − 1.
  static constexpr int kRiseBand = 32;
  // Sparse tables over bands of sample intervals (first_order_rise(), convexity_range()): a
  // block holds level after level, level l from start[l] on, with per band b the merge of bands
  // b … b + 2^l − 1 (level 0: the bands themselves); any range of bands is then the merge of two
  // overlapping runs.
  using LevelStarts = std::array<std::size_t, 32>;
  static std::size_t band_levels(int bands, LevelStarts& start);  // fills start; the block's length
  template <class T, class Merge>
  static void fill_band_runs(T* block, int bands, const LevelStarts& start, Merge merge) {
    for (int l = 1; (1 << l) <= bands; ++l)
      for (int b = 0; b + (1 << l) <= bands; ++b)
        block[start[static_cast<std::size_t>(l)] + static_cast<std::size_t>(b)] =
            merge(block[start[static_cast<std::size_t>(l - 1)] + static_cast<std::size_t>(b)],
                  block[start[static_cast<std::size_t>(l - 1)] + static_cast<std::size_t>(b + (1 << (l - 1)))]);
  }
  template <class T, class Merge>
  [[gnu::always_inline]] static T band_range(const T* block, const LevelStarts& start, int b_lo, int b_hi, Merge merge) {
    const int level = std::bit_width(static_cast<unsigned>(b_hi - b_lo + 1)) - 1;
    const T* runs = block + start[static_cast<std::size_t>(level)];
    return merge(runs[b_lo], runs[b_hi - (1 << level) + 1]);
  }
  static FirstOrderRise larger_rise(const FirstOrderRise& u, const FirstOrderRise& v) {
    return {u.slope > v.slope ? u.slope : v.slope, u.growth > v.growth ? u.growth : v.growth, u.jump > v.jump ? u.jump : v.jump,
            u.side > v.side ? u.side : v.side};
  }
  static ConvexityRange wider_convexity(const ConvexityRange& u, const ConvexityRange& v) {
    return {std::min(u.lo, v.lo), std::max(u.hi, v.hi)};
  }
  std::vector<FirstOrderRise> rise_flat_;  // one block for every row and flank
  LevelStarts rise_level_start_{};
  void build_rise_bands();
  // convexity_range() per band of kConvexityBand intervals and over runs of 2^l bands, a block
  // per row and flank ([(row * 2 + (flank == Cw)) * convexity_block_]), level l at
  // convexity_level_start_[l] in it.
  std::vector<ConvexityRange> convexity_bands_;
  std::size_t convexity_block_ = 0;
  LevelStarts convexity_level_start_{};
  void build_convexity_bands();
  // The jet of sample interval i's cubic at t ∈ [0, 1], radius r = r_min + (i + t)·dr
  // (flank_jet() within one interval, its ends included: both sides of a knot). False without
  // material at either end.
  bool interval_jet(int tooth, Flank flank, int i, double t, FlankJet* jet, double r) const;

  double tan_half_pitch_ = 0;
  std::vector<Eigen::Vector2d> tooth_axis_;  // (cos, sin) of each tooth's centre-line angle
  Eigen::Vector2d pitch_axis_;  // (cos, sin) of the pitch angle
  std::vector<Eigen::Vector2d> probe_points_;  // [(tooth * 2 + cw) * kProbeRadii + i]
  std::vector<std::uint32_t> probe_material_;  // [tooth * 2 + cw]
  std::vector<Eigen::Vector2d> tooth_centres_;
  double tooth_bound_ = 0;
};

}  // namespace gearsim::contact
