#include "analysis/characteristic_frequencies.hpp"

#include <cmath>
#include <numbers>
#include <numeric>
#include <string>

#include "core/errors.hpp"

namespace gearsim {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

void require_teeth(const char* what, const char* key, int z) {
  if (z < 1) throw InputError(std::string(what) + ": " + key + ": expected at least 1 tooth, got " + std::to_string(z));
}

void require_speed_and_harmonics(const char* what, double speed_rad_s, int harmonics) {
  if (!std::isfinite(speed_rad_s)) throw InputError(std::string(what) + ": input speed must be a finite number of rad/s");
  if (harmonics < 1) throw InputError(std::string(what) + ": mesh_harmonics: expected at least 1, got " + std::to_string(harmonics));
}

const char* member_name(PlanetaryMember m) {
  switch (m) {
    case PlanetaryMember::Sun:
      return "sun";
    case PlanetaryMember::Carrier:
      return "carrier";
    case PlanetaryMember::Ring:
      return "ring";
  }
  return "?";
}

void add_mesh_harmonics(GearTrainFrequencies& g, int harmonics, const char* fundamental_formula) {
  g.frequencies.push_back({"mesh", "mesh frequency", g.mesh_hz, fundamental_formula, FrequencyKind::Mesh});
  for (int h = 2; h <= harmonics; ++h) {
    const std::string n = std::to_string(h);
    g.frequencies.push_back({"mesh_" + n, "mesh harmonic " + n, h * g.mesh_hz, n + "·f_m", FrequencyKind::Mesh});
  }
}

}  // namespace

const CharacteristicFrequency& GearTrainFrequencies::at(const std::string& key) const {
  for (const CharacteristicFrequency& f : frequencies)
    if (f.key == key) return f;
  throw InputError("characteristic frequencies: no frequency named \"" + key + "\"");
}

PlanetarySpeeds planetary_speeds(const PlanetaryTrainSpec& s) {
  const char* what = "planetary frequencies";
  require_teeth(what, "sun_teeth", s.sun_teeth);
  require_teeth(what, "planet_teeth", s.planet_teeth);
  require_teeth(what, "ring_teeth", s.ring_teeth);
  if (s.planets < 1) throw InputError(std::string(what) + ": planets: expected at least 1, got " + std::to_string(s.planets));
  if (s.fixed == s.input) throw InputError(std::string(what) + ": the " + member_name(s.fixed) + " cannot be both fixed and the input");
  require_speed_and_harmonics(what, s.input_speed_rad_s, s.mesh_harmonics);
  const double zs = s.sun_teeth, zp = s.planet_teeth, zr = s.ring_teeth;
  // Willis in the form z_s·ω_s + z_r·ω_r = (z_s + z_r)·ω_c; one member at 0, one at the input.
  double w[3] = {0.0, 0.0, 0.0};  // sun, carrier, ring
  w[static_cast<int>(s.input)] = s.input_speed_rad_s;
  double& ws = w[0];
  double& wc = w[1];
  double& wr = w[2];
  const PlanetaryMember free_member = static_cast<PlanetaryMember>(3 - static_cast<int>(s.fixed) - static_cast<int>(s.input));
  switch (free_member) {
    case PlanetaryMember::Sun:
      ws = ((zs + zr) * wc - zr * wr) / zs;
      break;
    case PlanetaryMember::Carrier:
      wc = (zs * ws + zr * wr) / (zs + zr);
      break;
    case PlanetaryMember::Ring:
      wr = ((zs + zr) * wc - zs * ws) / zr;
      break;
  }
  PlanetarySpeeds v;
  v.sun_rad_s = ws;
  v.carrier_rad_s = wc;
  v.ring_rad_s = wr;
  v.planet_relative_rad_s = -(zs / zp) * (ws - wc);
  v.planet_rad_s = wc + v.planet_relative_rad_s;
  return v;
}

GearTrainFrequencies planetary_frequencies(const PlanetaryTrainSpec& s) {
  const PlanetarySpeeds v = planetary_speeds(s);
  const double zp = s.planet_teeth, zr = s.ring_teeth, n = s.planets;
  auto hz = [](double w_rad_s) { return std::abs(w_rad_s) / kTwoPi; };
  GearTrainFrequencies g;
  g.mesh_hz = zr * hz(v.ring_rad_s - v.carrier_rad_s);  // = z_s·|f_s − f_c|
  auto add = [&g](const char* key, const char* name, double f, const char* formula, FrequencyKind kind) {
    g.frequencies.push_back({key, name, f, formula, kind});
  };
  using K = FrequencyKind;
  if (s.fixed != PlanetaryMember::Sun) add("sun_shaft", "sun rotation", hz(v.sun_rad_s), "|ω_s|/2π", K::Shaft);
  if (s.fixed != PlanetaryMember::Carrier)
    add("carrier_shaft", "carrier rotation", hz(v.carrier_rad_s), "f_c = |ω_c|/2π, z_s·ω_s + z_r·ω_r = (z_s + z_r)·ω_c", K::Shaft);
  if (s.fixed != PlanetaryMember::Ring) add("ring_shaft", "ring rotation", hz(v.ring_rad_s), "|ω_r|/2π", K::Shaft);
  add("planet_spin", "planet spin (absolute)", hz(v.planet_rad_s), "|ω_c − (z_s/z_p)(ω_s − ω_c)|/2π", K::Shaft);
  add("planet_spin_relative", "planet spin relative to the carrier", hz(v.planet_relative_rad_s), "(z_s/z_p)·|f_s − f_c| = f_m/z_p",
      K::Shaft);
  add_mesh_harmonics(g, s.mesh_harmonics, "f_m = z_r·|f_r − f_c| = z_s·|f_s − f_c|");
  add("sun_fault", "sun local fault", n * hz(v.sun_rad_s - v.carrier_rad_s), "N·|f_s − f_c| = N·f_m/z_s", K::Fault);
  add("planet_fault", "planet local fault (one flank)", g.mesh_hz / zp, "f_m/z_p", K::Fault);
  add("planet_fault_both_flanks", "planet local fault (both flanks: meets sun and ring)", 2.0 * g.mesh_hz / zp, "2·f_m/z_p", K::Fault);
  add("ring_fault", "ring local fault", n * hz(v.ring_rad_s - v.carrier_rad_s), "N·|f_r − f_c| = N·f_m/z_r", K::Fault);
  if (s.fixed != PlanetaryMember::Carrier) add("planet_pass", "planet pass (housing)", n * hz(v.carrier_rad_s), "N·|f_c|", K::Pass);
  return g;
}

GearTrainFrequencies gear_pair_frequencies(const GearPairSpec& s) {
  const char* what = "gear pair frequencies";
  require_teeth(what, "driver_teeth", s.driver_teeth);
  require_teeth(what, "driven_teeth", s.driven_teeth);
  require_speed_and_harmonics(what, s.driver_speed_rad_s, s.mesh_harmonics);
  const double z1 = s.driver_teeth, z2 = s.driven_teeth;
  const double f1 = std::abs(s.driver_speed_rad_s) / kTwoPi;
  GearTrainFrequencies g;
  g.mesh_hz = z1 * f1;
  g.frequencies.push_back({"driver_shaft", "driver rotation", f1, "f_1 = |ω_1|/2π", FrequencyKind::Shaft});
  g.frequencies.push_back({"driven_shaft", "driven rotation", f1 * z1 / z2, "f_2 = f_1·z_1/z_2", FrequencyKind::Shaft});
  add_mesh_harmonics(g, s.mesh_harmonics, "f_m = z_1·f_1 = z_2·f_2");
  const double common = std::gcd(s.driver_teeth, s.driven_teeth);
  g.frequencies.push_back({"hunting_tooth", "hunting tooth (same tooth pair meets again)", g.mesh_hz * common / (z1 * z2),
                           "f_m·gcd(z_1, z_2)/(z_1·z_2)", FrequencyKind::Fault});
  return g;
}

}  // namespace gearsim
