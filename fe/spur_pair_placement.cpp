#include "fe/spur_pair_placement.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "core/errors.hpp"
#include "geometry/gear_profile.hpp"
#include "fe/closing_turn.hpp"
#include "fe/gear_mesh_regions.hpp"
#include "fe/planetary_positions.hpp"
#include "geometry/constants.hpp"

namespace gearsim::fe {
namespace {

using gearsim::constants::kPi;

GearSpec spec_of(const SpurPairDef& d, const char* name, int teeth) {
  GearSpec s;
  s.name = name;
  s.teeth = teeth;
  s.module_m = d.module_m;
  s.pressure_angle_rad = d.pressure_angle_rad;
  s.face_width_m = d.face_width_m;
  s.thinning_per_flank_m = d.thinning_per_flank_m;
  // The bore follows from the root circle.
  s.bore_diameter_m = d.bore_over_root * 2.0 * gear_dimensions(s).root_radius_m;
  validate_gear_spec(s);
  return s;
}

// True when the pinion's Ccw flank touches the wheel (exact outlines, flank tables).
bool touches(const contact::FlankTable& pinion, const contact::PlanarPose& pp, const contact::FlankTable& wheel,
             const contact::PlanarPose& wp) {
  for (const auto& c : contact::find_tooth_contacts(pinion, pp, wheel, wp))
    if (c.flank_a == Flank::Ccw) return true;
  return false;
}

double wrap_angle(double a) { return std::remainder(a, 2.0 * kPi); }

// A mesh edge placed in the plane, relative to the wheel centre: material on its left (the edges
// of counter-clockwise quads).
struct Edge {
  Eigen::Vector2d a, b;
};
std::vector<Edge> placed_edges(const QuadMesh2& m, const std::vector<QuadEdge>& edges, const contact::PlanarPose& pose,
                               const Eigen::Vector2d& origin) {
  const Eigen::Rotation2Dd rot(pose.angle_rad);
  std::vector<Edge> out;
  for (const QuadEdge& e : edges) {
    const auto [a, b] = edge_points(m, e);
    out.push_back({pose.centre_m + rot * a - origin, pose.centre_m + rot * b - origin});
  }
  return out;
}

// The turns δ ∈ [lo, kMaxClosingTurn_rad] of the wheel about the origin (its centre) at which a
// node crosses an edge of the other body into its material: sense +1, the nodes are the wheel's
// (turning by δ) and the edges the pinion's; sense −1, the nodes are the pinion's and the edges
// the wheel's (turning by δ). The smallest such turn is kept in `best`.
void entering_turns(const std::vector<Edge>& nodes_of, const std::vector<Edge>& edges, double sense, double lo, double& best) {
  std::vector<Eigen::Vector2d> nodes;
  for (const Edge& n : nodes_of) {
    nodes.push_back(n.a);
    nodes.push_back(n.b);
  }
  for (const Eigen::Vector2d& u : nodes) {
    const double rho2 = u.squaredNorm(), phi_u = std::atan2(u.y(), u.x());
    for (const Edge& e : edges) {
      // Points x = a + s (b − a), s ∈ [0, 1], at the node's radius.
      const Eigen::Vector2d d = e.b - e.a;
      const double A = d.squaredNorm(), B = e.a.dot(d), C = e.a.squaredNorm() - rho2;
      const double disc = B * B - A * C;
      if (disc < 0 || A == 0) continue;
      for (double sgn : {-1.0, 1.0}) {
        const double s = (-B + sgn * std::sqrt(disc)) / A;
        if (s < 0 || s > 1) continue;
        const Eigen::Vector2d x = e.a + s * d;
        // sense +1: the node turns by δ onto x; sense −1: the edge turns by δ onto the node.
        const double delta = wrap_angle(sense * (std::atan2(x.y(), x.x()) - phi_u));
        if (delta < lo || delta > kMaxClosingTurn_rad || delta >= best) continue;
        // Velocity of the node relative to the edge per unit δ, at the crossing.
        const Eigen::Vector2d at = sense > 0 ? x : u;
        const Eigen::Vector2d v = sense * Eigen::Vector2d(-at.y(), at.x());
        // The edge turned onto the crossing; material on its left.
        const Eigen::Vector2d dir = sense > 0 ? d : Eigen::Rotation2Dd(delta) * d;
        if (dir.x() * v.y() - dir.y() * v.x() > 0) best = delta;
      }
    }
  }
}

// First turn of the wheel (counter-clockwise, from `wheel`, not below lo) at which a node of one
// mesh's edges enters the other's edges; +inf when none up to kMaxClosingTurn_rad.
double polygon_closing_turn(const QuadMesh2& pm, const std::vector<QuadEdge>& pe, const contact::PlanarPose& pp, const QuadMesh2& wm,
                            const std::vector<QuadEdge>& we, const contact::PlanarPose& wp, double lo) {
  const std::vector<Edge> p = placed_edges(pm, pe, pp, wp.centre_m), w = placed_edges(wm, we, wp, wp.centre_m);
  double best = std::numeric_limits<double>::infinity();
  entering_turns(w, p, 1.0, lo, best);  // wheel nodes turned onto pinion edges
  entering_turns(p, w, -1.0, lo, best);  // pinion nodes met by turned wheel edges
  return best;
}

int wrap(int k, int n) { return ((k % n) + n) % n; }

}  // namespace

void validate_spur_pair(const SpurPairDef& d) {
  const std::string w = "spur pair: ";
  if (d.pinion_teeth < 5) throw InputError(w + "pinion_teeth must be >= 5, got " + std::to_string(d.pinion_teeth));
  if (d.wheel_teeth < 5) throw InputError(w + "wheel_teeth must be >= 5, got " + std::to_string(d.wheel_teeth));
  if (!(d.module_m > 0 && std::isfinite(d.module_m))) throw InputError(w + "module_m must be a length > 0 in m");
  if (!(d.pressure_angle_rad > 0.1 && d.pressure_angle_rad < 0.6)) throw InputError(w + "pressure_angle_rad must be in (0.1, 0.6) rad");
  if (!(d.face_width_m > 0 && std::isfinite(d.face_width_m))) throw InputError(w + "face_width_m must be a length > 0 in m");
  if (!(d.thinning_per_flank_m > 0 && d.thinning_per_flank_m < 0.1 * d.module_m))
    throw InputError(w + "thinning_per_flank_m must be in (0, 0.1 module) m, got " + std::to_string(d.thinning_per_flank_m) +
                     " (without backlash every tooth wedges in its mate's space and the contact forces are preload)");
  if (!(d.bore_over_root > 0 && d.bore_over_root < 1))
    throw InputError(w + "bore_over_root must be in (0, 1), got " + std::to_string(d.bore_over_root));
}

GearSpec pinion_spec(const SpurPairDef& d) {
  validate_spur_pair(d);
  return spec_of(d, "pinion", d.pinion_teeth);
}

GearSpec wheel_spec(const SpurPairDef& d) {
  validate_spur_pair(d);
  return spec_of(d, "wheel", d.wheel_teeth);
}

SpurPairPath spur_pair_path(const SpurPairDef& d) {
  const GearSpec ps = pinion_spec(d), ws = wheel_spec(d);
  const GearDimensions pd = gear_dimensions(ps), wd = gear_dimensions(ws);
  SpurPairPath p;
  p.pinion_base_radius_m = pd.base_radius_m;
  p.wheel_base_radius_m = wd.base_radius_m;
  p.centre_distance_m = pd.reference_radius_m + wd.reference_radius_m;
  const double span = p.centre_distance_m * std::sin(d.pressure_angle_rad);  // T1 to T2
  auto roll = [](double r, double rb) { return std::sqrt(std::max(r * r - rb * rb, 0.0)); };
  p.start_roll_m = span - roll(wd.tip_radius_m, wd.base_radius_m);
  p.end_roll_m = roll(pd.tip_radius_m, pd.base_radius_m);
  p.pitch_roll_m = pd.base_radius_m * std::tan(d.pressure_angle_rad);
  p.base_pitch_m = pd.base_pitch_m;
  p.contact_ratio = (p.end_roll_m - p.start_roll_m) / p.base_pitch_m;
  // The path must stay on both involutes (above each form circle).
  if (p.start_roll_m < roll(pd.form_radius_m, pd.base_radius_m))
    throw InputError("spur pair: the wheel's tip reaches below the pinion's form circle (interference), z = " +
                     std::to_string(d.pinion_teeth) + "/" + std::to_string(d.wheel_teeth));
  if (span - p.end_roll_m < roll(wd.form_radius_m, wd.base_radius_m))
    throw InputError("spur pair: the pinion's tip reaches below the wheel's form circle (interference), z = " +
                     std::to_string(d.pinion_teeth) + "/" + std::to_string(d.wheel_teeth));
  if (p.contact_ratio < 1.0) throw InputError("spur pair: contact ratio " + std::to_string(p.contact_ratio) + " < 1");
  return p;
}

std::vector<double> rolls_over_base_pitch(const SpurPairPath& path, int n) {
  if (n < 1) throw InputError("rolls_over_base_pitch: n must be >= 1, got " + std::to_string(n));
  std::vector<double> out;
  for (int i = 0; i < n; ++i) out.push_back(path.start_roll_m + (i + 0.5) * path.base_pitch_m / n);
  return out;
}

SpurPairPlacement place_spur_pair(const SpurPairDef& d, const QuadMesh2& pm, const QuadMesh2& wm, double roll_m) {
  const SpurPairPath path = spur_pair_path(d);
  if (!(roll_m >= path.start_roll_m - kSpurRollSlack_m && roll_m <= path.end_roll_m + kSpurRollSlack_m))
    throw InputError("spur pair position: roll length " + std::to_string(roll_m * 1e3) + " mm lies off the path of contact [" +
                     std::to_string(path.start_roll_m * 1e3) + ", " + std::to_string(path.end_roll_m * 1e3) + "] mm");
  const GearSpec ps = pinion_spec(d), ws = wheel_spec(d);
  const GearDimensions pd = gear_dimensions(ps), wd = gear_dimensions(ws);
  const double z1 = d.pinion_teeth, z2 = d.wheel_teeth, alpha = d.pressure_angle_rad;
  SpurPairPlacement out;
  out.roll_m = roll_m;
  // Pinion: tooth 0's Ccw flank through the line-of-action point at roll_m, polar angle
  // −α + atan(ℓ / r_b1) at radius √(r_b1² + ℓ²).
  const double rb1 = path.pinion_base_radius_m;
  const Eigen::Vector2d f = flank_point(ps, pd, 0, Flank::Ccw, std::hypot(rb1, roll_m));
  out.pinion.angle_rad = -alpha + std::atan2(roll_m, rb1) - std::atan2(f.y(), f.x());
  // Wheel: kinematic (its space centred on pinion tooth 0 at pinion angle 0, rolling at z1/z2).
  contact::PlanarPose wheel;
  wheel.centre_m = Eigen::Vector2d(path.centre_distance_m, 0.0);
  wheel.angle_rad = kPi + kPi / z2 - out.pinion.angle_rad * z1 / z2;
  // Closed on the exact outlines (a reference: 2 t / r_b2 for standard gears).
  const contact::FlankTable pt = flank_table_of(ps), wt = flank_table_of(ws);
  out.wheel_closing_exact_rad = closing_turn(
      [&](double delta) {
        contact::PlanarPose q = wheel;
        q.angle_rad += delta;
        return touches(pt, out.pinion, wt, q);
      },
      1.0, "spur pair (exact outlines)");
  // Pinion teeth near the path, the wheel space each sits in, their contact edges.
  const auto ptags = tag_toothed_edges(pm, ps, pd), wtags = tag_toothed_edges(wm, ws, wd);
  const double margin = kSpurSlotMargin_basePitches * path.base_pitch_m;
  const Eigen::Rotation2Dd to_world(out.pinion.angle_rad), to_wheel(-wheel.angle_rad);
  for (int k = -3; k <= 3 + static_cast<int>(path.contact_ratio); ++k) {
    SpurToothSlot s;
    s.offset = k;
    s.roll_m = roll_m + k * path.base_pitch_m;
    if (s.roll_m < path.start_roll_m - margin || s.roll_m > path.end_roll_m + margin) continue;
    s.pinion_tooth = wrap(k, d.pinion_teeth);
    const double a = 2.0 * kPi * k / z1;
    const Eigen::Vector2d tip_w = to_world * (pd.tip_radius_m * Eigen::Vector2d(std::cos(a), std::sin(a)));
    const Eigen::Vector2d tip_in_wheel = to_wheel * (tip_w - wheel.centre_m);
    s.wheel_space = wrap(static_cast<int>(std::floor(std::atan2(tip_in_wheel.y(), tip_in_wheel.x()) / (2.0 * kPi / z2))), d.wheel_teeth);
    s.on_path = s.roll_m >= path.start_roll_m - kSpurRollSlack_m && s.roll_m <= path.end_roll_m + kSpurRollSlack_m;
    s.pinion_edges = select_tooth_edges(pm, ptags, {{s.pinion_tooth}, false, false, Flank::Ccw});
    s.wheel_edges = select_tooth_edges(wm, wtags, {{s.wheel_space}, false, true, Flank::Ccw});
    const auto other = select_tooth_edges(wm, wtags, {{(s.wheel_space + 1) % d.wheel_teeth}, false, true, Flank::Cw});
    s.wheel_edges.insert(s.wheel_edges.end(), other.begin(), other.end());
    // This pair's own closing turn on the mesh boundaries (kept in fe_gap_m for now), searched
    // from half the exact closing back (an overlap of the boundaries at the kinematic position
    // shows as a negative turn; further back the trailing flanks would meet).
    s.fe_gap_m = polygon_closing_turn(pm, s.pinion_edges, out.pinion, wm, s.wheel_edges, wheel, -0.5 * out.wheel_closing_exact_rad);
    out.slots.push_back(s);
  }
  // Closed on the mesh boundaries: the first pair to touch; the others' gaps beyond it.
  double first = std::numeric_limits<double>::infinity();
  for (const SpurToothSlot& s : out.slots) first = std::min(first, s.fe_gap_m);
  if (!std::isfinite(first))
    throw InputError("spur pair position at roll " + std::to_string(roll_m * 1e3) + " mm: the mesh boundaries do not touch within " +
                     std::to_string(kMaxClosingTurn_rad) + " rad");
  out.wheel_closing_fe_rad = first;
  out.wheel = wheel;
  out.wheel.angle_rad += first;
  for (SpurToothSlot& s : out.slots) s.fe_gap_m = (s.fe_gap_m - first) * path.wheel_base_radius_m;
  return out;
}

}  // namespace gearsim::fe
