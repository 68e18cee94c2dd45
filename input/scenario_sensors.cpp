// The `sensors:` list of a scenario: virtual accelerometers on a housing body
// (physics::SensorDef), each value checked with its key named.
#include <cmath>
#include <numbers>
#include <set>
#include <sstream>

#include "input/gearset_file.hpp"
#include "input/safe_name.hpp"
#include "input/scenario_parts.hpp"

namespace gearsim::input::scenario_detail {

void parse_sensors(const std::vector<YamlMap>& entries, physics::Scenario& s) {
  std::set<std::string> names;
  const double step_rate = 1.0 / s.solver.time_step_s;
  for (const YamlMap& m : entries) {
    physics::SensorDef d;
    d.name = m.string("name");
    require_safe_name(m, "name", d.name, NameUse::Body);
    if (!names.insert(d.name).second) m.fail("name", "a second sensor named '" + d.name + "'");
    d.body = m.string("body");
    bool found = false;
    for (const physics::BodyDef& b : s.bodies) found = found || b.name == d.body;
    if (!found) m.fail("body", "no body named '" + d.body + "' (the housing body the sensor sits on, e.g. the ring)");
    d.angle_rad = angle_rad_or(m, "angle", 0.0);
    if (!m.has("window_width_deg") && !m.has("window_width_rad"))
      m.fail_here("a sensor needs window_width_deg (the full width of its planet-pass window)");
    d.window_width_rad = angle_rad_or(m, "window_width", 0.0);
    if (!(d.window_width_rad > 0 && d.window_width_rad <= 2 * std::numbers::pi + 1e-12))
      m.fail(m.has("window_width_deg") ? "window_width_deg" : "window_width_rad", "expected a width in (0°, 360°]");
    d.other_meshes_weight = number_within_or(m, "other_meshes_weight", 0.0, limits::kPathGain);
    d.resonance_hz = number_within(m, "resonance_hz", limits::kRate_Hz);
    if (!(d.resonance_hz < step_rate / 2)) {
      std::ostringstream msg;
      msg << "resonance " << d.resonance_hz << " Hz lies above the simulation's Nyquist frequency " << step_rate / 2 << " Hz (time step "
          << s.solver.time_step_s << " s)";
      m.fail("resonance_hz", msg.str());
    }
    d.damping_ratio = m.has("damping_ratio") ? positive(m, "damping_ratio", "damping ratio") : d.damping_ratio;
    if (!within(d.damping_ratio, limits::kDampingRatio)) m.fail("damping_ratio", limit_message(limits::kDampingRatio, d.damping_ratio));
    d.effective_mass_kg = number_within(m, "effective_mass_kg", limits::kMass_kg);
    d.noise_rms_m_s2 = number_within_or(m, "noise_rms_m_s2", 0.0, limits::kNoise_m_s2);
    d.sample_rate_hz = number_within(m, "sample_rate_hz", limits::kRate_Hz);
    const double steps = step_rate / d.sample_rate_hz;
    if (!(std::abs(steps - std::round(steps)) <= 1e-9 * steps && std::round(steps) >= 1)) {
      std::ostringstream msg;
      msg << "sample rate " << d.sample_rate_hz << " Hz is " << steps << " time steps, not a whole number: expected e.g. "
          << step_rate / std::max(1.0, std::floor(steps)) << " Hz or " << step_rate / std::ceil(steps) << " Hz";
      m.fail("sample_rate_hz", msg.str());
    }
    if (!s.sensors.empty() && d.sample_rate_hz != s.sensors.front().sample_rate_hz)
      m.fail("sample_rate_hz", "every sensor shares one acquisition rate (sensors.csv): expected " +
                                   std::to_string(s.sensors.front().sample_rate_hz) + " Hz as the first sensor's");
    m.reject_unknown_keys();
    s.sensors.push_back(d);
  }
}

}  // namespace gearsim::input::scenario_detail
