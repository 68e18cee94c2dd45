// The `pair:` scenario macro: two gears on hinges, meshing. External: the driver at the origin,
// the driven on +x; internal (one member a ring): the ring at the origin, the pinion on +x; the
// driven turned so that a tooth sits centred in the mating gap, and the tooth ratio as the
// transmission. Not the planetary macro (scenario_planetary.cpp).
#include <cmath>

#include "core/errors.hpp"
#include "geometry/constants.hpp"
#include "geometry/gear_mesh.hpp"
#include "input/gear_train.hpp"
#include "input/safe_name.hpp"
#include "input/scenario_macros_detail.hpp"

namespace gearsim::input::scenario_detail {
namespace {

namespace fs = std::filesystem;
using gearsim::constants::kPi;

physics::BodyDef pair_member(const YamlMap& m, const std::string& fallback_name, const fs::path& dir) {
  physics::BodyDef b;
  b.name = m.string_or("name", fallback_name);
  require_safe_name(m, "name", b.name, NameUse::Body);
  parse_shape_and_mass(m, b, dir);
  m.reject_unknown_keys();
  if (!b.gear && !b.mesh) m.fail_here("a pair member needs a shape: gear, gear_from or mesh");
  if (b.mesh && !b.mesh->teeth) m.fail("mesh", "a toothless mesh (teeth: none) cannot be a pair member");
  return b;
}

double tooth0_of(const physics::BodyDef& b) { return b.gear ? b.gear->tooth0_angle_rad : b.mesh->teeth->tooth0_angle_rad; }

}  // namespace

Expansion expand_pair(const YamlMap& m, const fs::path& dir) {
  physics::BodyDef a = pair_member(m.map("driver"), "driver", dir);
  physics::BodyDef b = pair_member(m.map("driven"), "driven", dir);
  if (a.name == b.name) m.fail("driven", "driver and driven have the same name '" + a.name + "'");
  // An internal pair: a pinion inside a ring, either of them the driver. The mesh figures take
  // the external gear first (ext, in).
  const bool internal = is_internal(a) || is_internal(b);
  if (is_internal(a) && is_internal(b)) m.fail("driven", "two internal gears cannot mesh");
  const physics::BodyDef& ext = is_internal(a) ? b : a;
  const physics::BodyDef& in = is_internal(a) ? a : b;
  const char* ext_key = is_internal(a) ? "driven" : "driver";
  const char* in_key = is_internal(a) ? "driver" : "driven";
  double centre_distance_m = 0;
  std::optional<physics::PairTableDef> table;
  if (a.gear && b.gear) {
    // Generated gears: the zero-backlash distance unless given; either way the mesh must work.
    try {
      centre_distance_m =
          number_within_or(m, "centre_distance_m", zero_backlash_centre_distance(*ext.gear, *in.gear), limits::kCentreDistance_m);
      analyse_mesh(*ext.gear, *in.gear, centre_distance_m);
    } catch (const InputError& e) {
      m.fail(m.has("centre_distance_m") ? "centre_distance_m" : "driven", e.what());
    }
  } else {
    // A mesh member: its recognised involutes give the same figures (without them the centre
    // distance must be given, and the start checks alone judge the mesh).
    std::string why;
    const std::optional<InvoluteTeeth> te = involutes_of(ext, why);
    if (!te && !m.has("centre_distance_m")) m.fail(ext_key, why + ", so the centre distance cannot be derived: give centre_distance_m");
    const std::optional<InvoluteTeeth> ti = involutes_of(in, why);
    if (!ti && !m.has("centre_distance_m")) m.fail(in_key, why + ", so the centre distance cannot be derived: give centre_distance_m");
    centre_distance_m = number_within_or(m, "centre_distance_m", 0.0, limits::kCentreDistance_m);  // 0: derived
    if (te && ti) {
      const bool derived = !m.has("centre_distance_m");
      std::string note;
      if (derived) try {
          const PairPlacement placed = place_pair(*te, *ti, "pair '" + a.name + "'–'" + b.name + "'");
          centre_distance_m = placed.centre_distance_m;
          note = placed.note;
        } catch (const InputError& e) {
          m.fail("driven", e.what());
        }
      table = checked_pair_table(m, a.name, b.name, *te, *ti, centre_distance_m, derived, "driven");
      table->placement_note = note;
      centre_distance_m = table->figures.centre_distance_m;
    }
  }
  if (!(centre_distance_m > 0)) m.fail("centre_distance_m", "expected a positive centre distance in m");
  const Eigen::Vector3d origin = vec3_within_or(m, "origin_m", Eigen::Vector3d::Zero(), limits::kPosition_m);
  m.reject_unknown_keys();

  // Placing: external, the driver at the origin and the driven on +x; internal, the ring at the
  // origin and the pinion on +x. The pitch point lies on the line of centres, seen from each
  // centre in direction phi: external +x from the driver and −x (π) from the driven; internal
  // +x from both. Tooth fractions f there (0 at a tooth centre, ½ in a gap) satisfy
  // f_driver + f_driven ≡ ½ externally (see planetary.cpp); internally the two turn the same way
  // and f_ring − f_pinion ≡ ½ (a pinion tooth in a ring gap). b is turned to match a.
  const double za = teeth_of(a), zb = teeth_of(b);
  const double phi_a = 0.0, phi_b = internal ? 0.0 : kPi;
  const double fa = (phi_a - tooth0_of(a)) * za / (2 * kPi);
  const double fa01 = fa - std::floor(fa), fb = internal ? fa01 + 0.5 : 0.5 - fa01;
  const double spin_b = phi_b - tooth0_of(b) - (fb - std::floor(fb)) * 2 * kPi / zb;
  const Eigen::Vector3d beside = origin + Eigen::Vector3d(centre_distance_m, 0, 0);
  a.pose.position_m = internal && !is_internal(a) ? beside : origin;
  b.pose.position_m = internal && is_internal(b) ? origin : beside;
  b.pose.orientation = about_z(spin_b);
  Expansion e;
  e.joints = {hinge(a.name, "ground", a.pose.position_m), hinge(b.name, "ground", b.pose.position_m)};
  // With te = θ_input − ratio·θ_output: an external pair turns opposite ways, θ_driver =
  // −(z_driven/z_driver)·θ_driven (ratio < 0); an internal one the same way (ratio > 0).
  e.transmission = physics::TransmissionDef{a.name, b.name, (internal ? zb : -zb) / za};
  e.bodies = {a, b};
  if (table) e.pair_tables.push_back(*table);
  return e;
}

}  // namespace gearsim::input::scenario_detail
