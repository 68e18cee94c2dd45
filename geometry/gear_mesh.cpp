#include "geometry/gear_mesh.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "core/errors.hpp"
#include "geometry/gear_profile.hpp"
#include "geometry/involute.hpp"
#include "geometry/tessellate.hpp"
#include "geometry/constants.hpp"

namespace gearsim {
namespace {

using Eigen::Vector2d;
using gearsim::constants::kPi;

// Error-free copy of a spec: the interference check is about the design, not the errors.
GearSpec nominal(GearSpec s) {
  s.errors = {};
  s.thinning_per_flank_m = 0;
  s.tooth0_angle_rad = 0;
  return s;
}

// Signed distance of p to a closed polygon: positive inside.
double signed_distance(const Polygon2& poly, const Vector2d& p) {
  double d = 1e300;
  bool inside = false;
  const auto& v = poly.points;
  for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
    d = std::min(d, distance_to_segment(p, v[j], v[i]));
    if ((v[i].y() > p.y()) != (v[j].y() > p.y()) &&
        p.x() < (v[j].x() - v[i].x()) * (p.y() - v[i].y()) / (v[j].y() - v[i].y()) + v[i].x())
      inside = !inside;
  }
  return inside ? d : -d;
}

// Tip corners (both flanks) of tooth 0 of gear g.
std::vector<Vector2d> tip_corners(const GearSpec& g, const GearDimensions& d) {
  return {flank_point(g, d, 0, Flank::Ccw, d.tip_radius_m), flank_point(g, d, 0, Flank::Cw, d.tip_radius_m)};
}

// Deepest penetration of `mover`'s tooth-0 tip corners into `host`'s material while the pair
// turns through ±1.5 pitches of `host`. The host sits at the origin with the pitch point on +x and
// a tooth space centred there at θ = 0; the mover's tooth 0 points at the pitch point. An
// external mover turns by −θ·z_h/z_m, one of an internal pair by +θ·z_h/z_m.
double tip_penetration(const GearSpec& host, const GearSpec& mover, double a) {
  const bool host_internal = host.kind == GearKind::Internal;
  const bool mover_internal = mover.kind == GearKind::Internal;
  const bool internal_pair = host_internal || mover_internal;
  const GearOutline oh = make_gear_outline(host);
  const Polygon2& toothed = host_internal ? oh.outline.holes.front() : oh.outline.outer;
  const GearDimensions dm = gear_dimensions(mover);
  const std::vector<Vector2d> corners = tip_corners(mover, dm);
  const double ratio = static_cast<double>(host.teeth) / mover.teeth;
  // Pitch point on +x: an external or ring mover's centre lies at (±a, 0).
  const Vector2d centre(mover_internal ? -a : a, 0.0);
  const double host_phase = kPi / host.teeth;
  const double mover_phase = internal_pair ? 0.0 : kPi;
  constexpr int kSamples = 3000;
  double worst = -1e300;
  for (int i = 0; i <= kSamples; ++i) {
    const double theta = (-1.5 + 3.0 * i / kSamples) * 2 * kPi / host.teeth;
    const double mover_angle = mover_phase + (internal_pair ? 1.0 : -1.0) * theta * ratio;
    for (const Vector2d& c : corners) {
      const Vector2d w = centre + Eigen::Rotation2Dd(mover_angle) * c;
      const Vector2d in_host = Eigen::Rotation2Dd(-(theta + host_phase)) * w;
      const double sd = signed_distance(toothed, in_host);
      // Host material: inside the toothed loop of an external gear, outside that of a ring.
      worst = std::max(worst, host_internal ? -sd : sd);
    }
  }
  return worst;
}

}  // namespace

double zero_backlash_centre_distance(const GearSpec& a, const GearSpec& b) {
  const bool internal = b.kind == GearKind::Internal;
  const double alpha = a.pressure_angle_rad;
  const double zsum = internal ? b.teeth - a.teeth : a.teeth + b.teeth;
  const double xsum = internal ? b.profile_shift - a.profile_shift : a.profile_shift + b.profile_shift;
  const double inv_w = involute(alpha) + 2.0 * std::tan(alpha) * xsum / zsum;
  if (inv_w < 0) throw InputError("mesh " + a.name + "–" + b.name + ": profile shifts give no working pressure angle");
  const double alpha_w = inverse_involute(inv_w);
  return 0.5 * a.module_m * zsum * std::cos(alpha) / std::cos(alpha_w);
}

MeshGeometry analyse_mesh(const GearSpec& a, const GearSpec& b, double centre_distance_m) {
  const std::string pair = "mesh " + a.name + "–" + b.name;
  if (a.kind != GearKind::External) throw InputError(pair + ": the first gear must be external");
  if (std::abs(a.module_m - b.module_m) > 1e-12 ||
      std::abs(a.pressure_angle_rad - b.pressure_angle_rad) > 1e-12)
    throw InputError(pair + ": gears of different module or pressure angle cannot mesh");
  const GearDimensions da = gear_dimensions(a), db = gear_dimensions(b);
  MeshGeometry m;
  m.internal = b.kind == GearKind::Internal;
  m.ratio = static_cast<double>(b.teeth) / a.teeth;
  m.centre_distance_m = centre_distance_m;
  m.base_pitch_m = da.base_pitch_m;
  const double rb_sum = m.internal ? db.base_radius_m - da.base_radius_m : da.base_radius_m + db.base_radius_m;
  if (!(centre_distance_m > rb_sum))
    throw InputError(pair + ": centre distance " + std::to_string(centre_distance_m * 1e3) +
                     " mm does not exceed the base circles' " + std::to_string(rb_sum * 1e3) + " mm");
  m.working_pressure_angle_rad = std::acos(rb_sum / centre_distance_m);
  const double line = centre_distance_m * std::sin(m.working_pressure_angle_rad);  // T1T2
  const double tip_roll_a = roll_length_at(da.base_radius_m, da.tip_radius_m);
  const double tip_roll_b = roll_length_at(db.base_radius_m, db.tip_radius_m);
  m.form_roll_a_m = roll_length_at(da.base_radius_m, da.form_radius_m);
  m.form_roll_b_m = roll_length_at(db.base_radius_m, db.form_radius_m);
  double end_a, end_b;  // roll lengths where each gear's own tip ends contact
  if (!m.internal) {
    m.active_start_roll_a_m = line - tip_roll_b;
    m.active_start_roll_b_m = line - tip_roll_a;
    m.contact_length_m = tip_roll_a + tip_roll_b - line;
    end_a = tip_roll_a;
    // Contact runs on a from max(active start, form) to its tip.
    const double start_a = std::max(m.active_start_roll_a_m, m.form_roll_a_m);
    const double end_a_limited = std::min(end_a, line - m.form_roll_b_m);
    m.effective_contact_ratio = (end_a_limited - start_a) / m.base_pitch_m;
    (void)end_b;
  } else {
    // Internal: the ring's roll length equals the pinion's plus T1T2; the ring's involute runs
    // from its tip (inside) out to its form circle.
    m.active_start_roll_a_m = tip_roll_b - line;         // ring tip meets pinion here
    m.active_start_roll_b_m = tip_roll_a + line;         // pinion tip meets ring here (deepest)
    m.contact_length_m = tip_roll_a - tip_roll_b + line;
    const double start_a = std::max(m.active_start_roll_a_m, m.form_roll_a_m);
    const double end_a_limited = std::min(tip_roll_a, m.form_roll_b_m - line);
    m.effective_contact_ratio = (end_a_limited - start_a) / m.base_pitch_m;
  }
  m.contact_ratio = m.contact_length_m / m.base_pitch_m;
  std::ostringstream note;
  note.precision(4);
  if (m.active_start_roll_a_m < m.form_roll_a_m) {
    note << b.name << "'s tips reach " << a.name << " below its form circle (roll length "
         << m.active_start_roll_a_m * 1e3 << " mm < " << m.form_roll_a_m * 1e3 << " mm): contact in the fillet region";
    m.problems.push_back(note.str());
    note.str("");
  }
  const bool b_beyond = m.internal ? m.active_start_roll_b_m > m.form_roll_b_m
                                   : m.active_start_roll_b_m < m.form_roll_b_m;
  if (b_beyond) {
    note << a.name << "'s tips reach " << b.name << " beyond its form circle (roll length "
         << m.active_start_roll_b_m * 1e3 << " mm vs form " << m.form_roll_b_m * 1e3 << " mm)";
    m.problems.push_back(note.str());
    note.str("");
  }
  if (m.contact_ratio < 1.0) m.problems.push_back("contact ratio below 1: the mesh is not continuous");
  m.tip_interference_a_m = std::max(0.0, tip_penetration(nominal(a), nominal(b), centre_distance_m));
  m.tip_interference_b_m = std::max(0.0, tip_penetration(nominal(b), nominal(a), centre_distance_m));
  // Below the tessellation's own chordal deviation a "penetration" is only polyline noise.
  const double noise = std::max(a.chordal_deviation_m, b.chordal_deviation_m);
  if (m.tip_interference_a_m > noise) {
    note << b.name << "'s tips cut into " << a.name << " by " << m.tip_interference_a_m * 1e6 << " µm (tip/fillet interference)";
    m.problems.push_back(note.str());
    note.str("");
  }
  if (m.tip_interference_b_m > noise) {
    note << a.name << "'s tips cut into " << b.name << " by " << m.tip_interference_b_m * 1e6 << " µm (tip/fillet interference)";
    m.problems.push_back(note.str());
  }
  return m;
}

}  // namespace gearsim
