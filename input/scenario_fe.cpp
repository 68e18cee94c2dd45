// The scenario's `fe:` section: settings of the finite-element loaded transmission error
// (`gearsim fe-te`). Every key is optional; defaults are fe/constants.hpp's.
#include <cmath>
#include <sstream>

#include "input/scenario_parts.hpp"
#include "fe/constants.hpp"

namespace gearsim::input::scenario_detail {

physics::FeTeDef parse_fe(const YamlMap& m, const physics::Scenario& s) {
  if (!s.planetary)
    m.fail("fe",
           "fe-te solves planetary trains of generated gears: the scenario needs the planetary: macro with "
           "the gear names of a spec (a set of CAD meshes has no finite-element model yet)");
  physics::FeTeDef f;
  using namespace limits;
  f.flank_size_m = number_within_or(m, "flank_size_m", fe::kDefaultFeTeFlankSize_m, kFeElementSize_m);
  f.core_size_m = number_within_or(m, "core_size_m", std::max(fe::kDefaultCoreElementSize_m, f.flank_size_m), kFeElementSize_m);
  if (f.core_size_m < f.flank_size_m) m.fail("core_size_m", "expected at least flank_size_m");
  f.transition_m = number_within_or(m, "transition_m", fe::kDefaultSizeTransition_m, kFeTransition_m);
  f.max_sagitta_m = number_within_or(m, "max_sagitta_m", fe::kDefaultMaxSagitta_m, kFeSagitta_m);
  f.thinning_per_flank_m = number_within_or(m, "thinning_per_flank_m", 0.0, kThinning_m);
  f.friction = m.number_or("friction", fe::kDefaultFlankFriction);
  if (!(f.friction >= 0) || f.friction > 1) m.fail("friction", "expected a Coulomb coefficient 0 to 1");
  f.element_type = m.choice_or("element_type", {"CPS4R", "CPS4"}, "CPS4R");
  f.positions_per_mesh = m.integer_or("positions_per_mesh", fe::kDefaultPositionsPerMesh);
  if (f.positions_per_mesh < 1 || f.positions_per_mesh > 1000) m.fail("positions_per_mesh", "expected 1 to 1000 solves per mesh period");
  f.mesh_periods = m.number_or("mesh_periods", 1.0);
  if (!(f.mesh_periods > 0) || f.mesh_periods > 200) m.fail("mesh_periods", "expected 0 < mesh periods ≤ 200");
  f.jobs = m.integer_or("jobs", fe::kDefaultFeJobs);
  if (f.jobs < 1 || f.jobs > 64) m.fail("jobs", "expected 1 to 64 ccx processes");

  // Torque: given, or the carrier's constant load reflected to the sun through the ratio.
  if (const auto t = m.optional_number("sun_torque_N_m")) {
    if (!(*t > 0) || !within(*t, limits::kTorque_N_m))
      m.fail("sun_torque_N_m", "expected a positive input torque on the sun (it drives, +z): " + limit_message(limits::kMaxTorque_N_m, *t));
    f.sun_torque_N_m = *t;
    f.torque_source = "fe.sun_torque_N_m";
  } else {
    if (!s.transmission) m.fail("sun_torque_N_m", "no transmission to reflect the output load through: give sun_torque_N_m");
    double out_load = 0;
    for (const physics::LoadDef& l : s.loads)
      if (l.joint == s.transmission->output_joint) out_load += l.constant_torque_N_m;
    if (!(out_load < 0))
      m.fail("sun_torque_N_m",
             "the output joint '" + s.transmission->output_joint + "' has no resisting constant load to reflect: give sun_torque_N_m");
    f.sun_torque_N_m = -out_load / s.transmission->ratio;
    std::ostringstream src;
    src << "loads: " << out_load << " N·m on " << s.transmission->output_joint << " / ratio " << s.transmission->ratio;
    f.torque_source = src.str();
  }

  // Teeth without backlash wedge in the FE (both flanks load): demand a clearance on both meshes.
  const physics::PlanetaryTrainDef& t = *s.planetary;
  auto backlash = [&](const GearSpec& a, const GearSpec& b) {
    return a.thinning_per_flank_m + b.thinning_per_flank_m + 2 * f.thinning_per_flank_m;
  };
  for (const GearSpec& p : t.planet_gears)
    if (!(backlash(t.spec.sun, p) > 0) || !(backlash(p, t.spec.ring) > 0))
      m.fail("thinning_per_flank_m",
             "the gears have no backlash allowance: without one every tooth wedges in its mate's space "
             "and both flanks carry load; give a thinning per flank in m (e.g. 20.0e-6)");
  m.reject_unknown_keys();
  return f;
}

}  // namespace gearsim::input::scenario_detail
