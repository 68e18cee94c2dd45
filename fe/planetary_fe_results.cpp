// One solved position of the planetary FE solve read from ccx's results: rotations and TE,
// contact forces and secant mesh stiffnesses, the torque the teeth take off the sun, the tracked
// tooth's root stresses. Not the deck (planetary_fe_deck.cpp) and not the solve (planetary_fe.cpp).
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "fe/ccx_dat.hpp"
#include "fe/constants.hpp"
#include "fe/planetary_fe_detail.hpp"

namespace gearsim::fe::planetary_detail {
namespace {

// Root-stress summary of one element set's block (rows: element, integration point, sxx, syy,
// szz, sxy, …; deck units MPa).
struct StressSummary {
  double s1_max = -std::numeric_limits<double>::infinity();
  double s2_min = std::numeric_limits<double>::infinity();
  double vm_max = 0;
};
StressSummary summarise_stress(const DatBlock& b) {
  StressSummary out;
  for (const auto& [id, v] : b.row_list) {
    if (v.size() < 5) throw std::runtime_error("ccx stress row of element " + std::to_string(id) + " is short");
    const double sx = v[1], sy = v[2], txy = v[4];
    const double c = 0.5 * (sx + sy), r = std::hypot(0.5 * (sx - sy), txy);
    out.s1_max = std::max(out.s1_max, c + r);
    out.s2_min = std::min(out.s2_min, c - r);
    out.vm_max = std::max(out.vm_max, std::sqrt(sx * sx - sx * sy + sy * sy + 3 * txy * txy));
  }
  return out;
}

// Contact forces (per planet, per sun-side tooth), secant mesh stiffnesses, the torque the teeth
// take off the sun and the loaded TE, from the contact totals in run.dat_path; sun_low and
// sun_full are the sun's rotations at the low and the full stage, rad.
void read_forces(PlanetaryFePosition& out, const PositionDeck& p, const PlanetaryFeDef& def, const CcxRunResult& run, double sun_low,
                 double sun_full) {
  const PlanetarySpec& ps = def.spec;
  const PlanetaryPosition& pos = p.pos;
  const GearDimensions &sd = p.sun_dims, &pd = p.planet_dims;
  const std::vector<std::vector<int>>& sun_mesh_teeth = p.sun_mesh_teeth;
  const auto totals = read_contact_totals(run.dat_path);
  auto totals_of = [&](const std::string& slave, double time) -> const ContactTotals& {
    for (auto it = totals.rbegin(); it != totals.rend(); ++it)
      if (it->slave == slave && std::abs(it->time - time) < 1e-6) return *it;
    throw std::runtime_error("ccx results lack the contact force of " + slave + " at time " + std::to_string(time) + " (" +
                             run.dat_path.string() + ")");
  };
  auto force_vector = [&](const std::string& slave, double time) -> Eigen::Vector3d {
    const ContactTotals& t = totals_of(slave, time);
    return {t.force[0], t.force[1], t.force[2]};  // N in the deck too
  };
  auto force = [&](const std::string& slave, double time) { return force_vector(slave, time).norm(); };
  // The sun's force on a planet: the sum over its teeth's pairs.
  auto sun_force = [&](int k, double time) {
    Eigen::Vector3d f = Eigen::Vector3d::Zero();
    for (int j : sun_mesh_teeth[static_cast<size_t>(k)]) f += force_vector("SSP" + std::to_string(k) + "T" + std::to_string(j), time);
    return f.norm();
  };
  const double rbs = sd.base_radius_m, rbp = pd.base_radius_m;
  auto secant = [](double dF, double approach) { return approach != 0 ? dF / approach : std::numeric_limits<double>::quiet_NaN(); };
  for (int k = 0; k < ps.planets; ++k) {
    const std::string n = std::to_string(k);
    out.sun_planet_force_N.push_back(sun_force(k, 3.0));
    out.planet_ring_force_N.push_back(force("SPR" + n, 3.0));
    out.sun_planet_force_low_N.push_back(sun_force(k, 2.0));
    out.planet_ring_force_low_N.push_back(force("SPR" + n, 2.0));
    const double dp = out.planet_rotation_rad[k] - out.planet_rotation_low_rad[k];
    out.sun_planet_stiffness_N_per_m.push_back(
        secant(out.sun_planet_force_N[k] - out.sun_planet_force_low_N[k], rbs * (sun_full - sun_low) + rbp * dp));
    out.planet_ring_stiffness_N_per_m.push_back(secant(out.planet_ring_force_N[k] - out.planet_ring_force_low_N[k], -rbp * dp));
  }
  // The torque the teeth take off the sun: the moment about the sun's centre of the contact
  // forces on the planet teeth, reversed. CPS4R bodies in ccx resist a rigid turn of their hub a
  // little (expanded to hourglass-controlled C3D8R; docs/fe-reference.md), so part of the applied torque
  // never reaches the teeth; the elastic TE is the sun's turn per N·m through the teeth, times T.
  auto sun_mesh_torque = [&](double time) {
    const auto& c = pos.sun.centre_m;
    double m = 0;
    for (int k = 0; k < ps.planets; ++k)
      for (int j : sun_mesh_teeth[static_cast<size_t>(k)]) {
        const ContactTotals& t = totals_of("SSP" + std::to_string(k) + "T" + std::to_string(j), time);
        // The sun pushes the planet tooth (slave) with the moment printed (N·mm about the origin);
        // the teeth take that much off the sun.
        m += (t.moment[2] - (c.x() * t.force[1] - c.y() * t.force[0]) * kDeckLength_per_m) / kDeckLength_per_m;
      }
    return m;
  };
  out.sun_mesh_torque_low_N_m = sun_mesh_torque(2.0);
  out.sun_mesh_torque_N_m = sun_mesh_torque(3.0);
  const double dm = out.sun_mesh_torque_N_m - out.sun_mesh_torque_low_N_m;
  out.te_elastic_rad = dm > 0 ? (sun_full - sun_low) / dm * def.sun_torque_N_m : std::numeric_limits<double>::quiet_NaN();
  out.te_loaded_rad = out.te_geometric_rad + out.te_elastic_rad;
  for (int k = 0; k < ps.planets; ++k) {
    std::vector<std::pair<int, double>> per_tooth;
    for (int j : sun_mesh_teeth[static_cast<size_t>(k)])
      per_tooth.emplace_back(j, force("SSP" + std::to_string(k) + "T" + std::to_string(j), 3.0));
    out.sun_mesh_tooth_force_N.push_back(std::move(per_tooth));
  }
}

// Root stresses of the tracked tooth's sets at the full torque (and σ1 at the low stage).
void read_root_stresses(PlanetaryFePosition& out, const PositionDeck& p, const std::vector<DatBlock>& blocks, const CcxRunResult& run) {
  const std::vector<RootSet>& root_sets = p.root_sets;
  const DeckDef& deck = p.deck;
  for (std::size_t i = 0; i < root_sets.size(); ++i) {
    const std::string& set = root_sets[i].name;
    auto stress_at = [&](double time) -> const DatBlock& {
      for (const DatBlock& b : blocks)
        if (b.quantity == "stresses" && b.set == set && std::abs(b.time - time) < 1e-6) return b;
      throw std::runtime_error("ccx results lack the stresses of " + set + " at time " + std::to_string(time) + " (" +
                               run.dat_path.string() + ")");
    };
    const StressSummary full = summarise_stress(stress_at(3.0)), low = summarise_stress(stress_at(2.0));
    RootStress r;
    r.tooth = root_sets[i].tooth;
    r.side = root_sets[i].side;
    r.sigma1_max_Pa = full.s1_max / kDeckStress_per_Pa;
    r.sigma2_min_Pa = full.s2_min / kDeckStress_per_Pa;
    r.von_mises_max_Pa = full.vm_max / kDeckStress_per_Pa;
    r.sigma1_max_low_Pa = low.s1_max / kDeckStress_per_Pa;
    r.elements = static_cast<int>(deck.stress_sets[i].elements.size());
    out.tracked_root_stress.push_back(r);
  }
}

}  // namespace

PlanetaryFePosition read_position(const PositionDeck& p, const PlanetaryFeDef& def, const CcxRunResult& run, double sun_turn_rad) {
  const PlanetarySpec& ps = def.spec;
  const PlanetaryPosition& pos = p.pos;
  const Deck& d = p.written;
  // Results at the end of the low (time 2) and full (time 3) load stages.
  const auto blocks = read_dat(run.dat_path);
  auto rotation = [&](int body, double time) {
    for (const DatBlock& b : blocks)
      if (b.quantity == "displacements" && b.set == "NROT" && std::abs(b.time - time) < 1e-6)
        return b.rows.at(d.layout[static_cast<size_t>(body)].rotation_node).at(0);
    throw std::runtime_error("ccx results lack the rotations at time " + std::to_string(time) + " (" + run.dat_path.string() + ")");
  };
  PlanetaryFePosition out;
  out.sun_turn_rad = sun_turn_rad;
  out.te_geometric_rad = pos.sun_closing_rad;
  const double sun_low = rotation(0, 2.0), sun_full = rotation(0, 3.0);
  out.te_fe_low_rad = pos.sun_closing_rad + sun_low;
  out.te_fe_full_rad = pos.sun_closing_rad + sun_full;
  for (int k = 0; k < ps.planets; ++k) {
    out.planet_rotation_low_rad.push_back(rotation(k + 1, 2.0));
    out.planet_rotation_rad.push_back(rotation(k + 1, 3.0));
  }
  read_forces(out, p, def, run, sun_low, sun_full);
  out.tracked = p.tracked;
  read_root_stresses(out, p, blocks, run);
  out.wall_time_s = run.wall_time_s;
  return out;
}

}  // namespace gearsim::fe::planetary_detail
