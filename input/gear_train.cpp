#include "input/gear_train.hpp"

#include "core/errors.hpp"

namespace gearsim::input {

int teeth_of(const physics::BodyDef& b) {
  if (b.gear) return b.gear->teeth;
  if (b.mesh && b.mesh->teeth) return b.mesh->teeth->teeth;
  return 0;
}

bool is_internal(const physics::BodyDef& b) {
  if (b.gear) return b.gear->kind == GearKind::Internal;
  return b.mesh && b.mesh->recognised && b.mesh->recognised->internal;  // a mesh as recognised
}

namespace {

// The planetary set t (sun, planets, ring, carrier named) as the frequencies' spec: which member
// stands still, which is driven, at what speed.
PlanetaryTrainSpec planetary_spec(const physics::Scenario& s, const GearTrain& t, const physics::BodyDef& ring, const std::string& where) {
  PlanetaryTrainSpec spec;
  spec.sun_teeth = t.sun_teeth;
  spec.planet_teeth = t.planet_teeth;
  spec.ring_teeth = t.ring_teeth;
  spec.planets = static_cast<int>(t.planets.size());
  // A ring held against rotation by a torsional support stands still like a welded one.
  bool ring_held = ring.fixed;
  for (const physics::JointDef& j : s.joints)
    ring_held = ring_held || (j.body == ring.name && j.parent == "ground" && j.bearing && j.bearing->torsional_stiffness_N_m_per_rad > 0);
  spec.fixed = ring_held ? PlanetaryMember::Ring : PlanetaryMember::Carrier;
  if (t.input_body == t.sun)
    spec.input = PlanetaryMember::Sun;
  else if (t.input_body == t.carrier)
    spec.input = PlanetaryMember::Carrier;
  else if (t.input_body == t.ring)
    spec.input = PlanetaryMember::Ring;
  else
    throw InputError(where + "the motor drives '" + t.input_body + "', not the sun, carrier or ring");
  spec.input_speed_rad_s = t.input_speed_rad_s;
  return spec;
}

}  // namespace

GearTrain gear_train_of(const physics::Scenario& s) {
  const std::string where = s.source.string() + ": ";
  auto parent_of = [&](const std::string& body) -> std::string {
    for (const physics::JointDef& j : s.joints)
      if (j.body == body) return j.parent;
    return "";  // welded or free: no joint
  };
  GearTrain t;
  for (const physics::JointDef& j : s.joints)
    if (j.bearing && j.bearing->radially_rigid)
      throw InputError(where + "a train of stages joined by shafts ('" + j.parent + "' to '" + j.body +
                       "'): the analysis takes one planetary set or one gear pair so far (the run's logs and summary.json hold "
                       "the train's speeds, ratio and mesh forces)");
  if (s.motors.empty()) throw InputError(where + "no motor: the analysis needs to know which member is the input");
  for (const physics::JointDef& j : s.joints)
    if (j.name == s.motors.front().joint) t.input_body = j.body;
  t.input_speed_rad_s = s.motors.front().target_speed_rad_s;
  std::vector<const physics::BodyDef*> gears;
  const physics::BodyDef* ring = nullptr;
  for (const physics::BodyDef& b : s.bodies)
    if (teeth_of(b) > 0) {
      gears.push_back(&b);
      if (is_internal(b)) ring = &b;
    }
  // A ring with gears on a carrier is a planetary set; a ring meshing one pinion, both about the
  // ground, is a gear pair (analysed below like an external one: same mesh and shaft rates).
  bool carried = false;
  for (const physics::BodyDef* g : gears) carried = carried || (g != ring && !parent_of(g->name).empty() && parent_of(g->name) != "ground");
  if (ring && (carried || gears.size() != 2)) {
    t.planetary = true;
    t.ring = ring->name;
    t.ring_teeth = teeth_of(*ring);
    for (const physics::BodyDef* g : gears) {
      if (g == ring) continue;
      const std::string parent = parent_of(g->name);
      if (parent == "ground" || parent.empty()) {
        if (!t.sun.empty())
          throw InputError(where + "two gears ('" + t.sun + "', '" + g->name +
                           "') turn about the ground: not a single-stage planetary set");
        t.sun = g->name;
        t.sun_teeth = teeth_of(*g);
      } else {
        if (!t.carrier.empty() && parent != t.carrier)
          throw InputError(where + "planets on two carriers ('" + t.carrier + "', '" + parent + "'): not a single-stage planetary set");
        t.carrier = parent;
        if (t.planet_teeth && teeth_of(*g) != t.planet_teeth) throw InputError(where + "planets with different tooth counts: not analysed");
        t.planet_teeth = teeth_of(*g);
        t.planets.push_back(g->name);
      }
    }
    if (t.sun.empty() || t.planets.empty())
      throw InputError(where + "an internal gear without a sun and planets on a carrier: not a planetary set");
    t.frequencies = planetary_frequencies(planetary_spec(s, t, *ring, where));
    return t;
  }
  if (gears.size() != 2)
    throw InputError(where + std::to_string(gears.size()) +
                     " gears and no internal one: only a planetary set or one gear pair is analysed");
  const bool first_drives = gears[0]->name == t.input_body;
  if (!first_drives && gears[1]->name != t.input_body)
    throw InputError(where + "the motor drives '" + t.input_body + "', neither gear of the pair");
  t.internal_pair = ring != nullptr;
  t.driver = first_drives ? gears[0]->name : gears[1]->name;
  t.driven = first_drives ? gears[1]->name : gears[0]->name;
  t.driver_teeth = teeth_of(first_drives ? *gears[0] : *gears[1]);
  t.driven_teeth = teeth_of(first_drives ? *gears[1] : *gears[0]);
  t.frequencies = gear_pair_frequencies({t.driver_teeth, t.driven_teeth, t.input_speed_rad_s, 3});
  return t;
}

}  // namespace gearsim::input
