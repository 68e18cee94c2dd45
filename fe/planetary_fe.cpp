#include "fe/planetary_fe.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <exception>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <limits>
#include <mutex>
#include <numbers>
#include <thread>

#include "core/errors.hpp"
#include "geometry/gear_dimensions.hpp"
#include "fe/ccx_dat.hpp"
#include "fe/constants.hpp"
#include "fe/deck.hpp"
#include "fe/gear_mesh_regions.hpp"
#include "fe/planetary_positions.hpp"
#include "fe/process.hpp"

namespace gearsim::fe {
namespace {

const GearSpec& planet_gear(const PlanetaryFeDef& def, int k) {
  return def.planet_gears.empty() ? def.spec.planet : def.planet_gears[static_cast<size_t>(k)];
}

FeMesh to_fe_mesh(const QuadMesh2& q) {
  FeMesh m;
  m.nodes_m = q.nodes;
  m.quads = q.quads;
  m.hub_nodes = q.bore_nodes;
  m.fixed_nodes = q.rim_nodes;
  m.boundary_edges = q.toothed_edges;
  return m;
}

// Toothed edges of a placed mesh whose mid-points lie within `radius` of `centre` (world, m).
std::vector<std::pair<int, int>> edges_near(const QuadMesh2& q, const contact::PlanarPose& pose,
                                            const Eigen::Vector2d& centre, double radius) {
  std::vector<std::pair<int, int>> out;
  const Eigen::Rotation2Dd rot(pose.angle_rad);
  for (const QuadEdge& e : q.toothed_edges) {
    const auto [a, b] = edge_points(q, e);
    const Eigen::Vector2d mid = pose.centre_m + rot * (0.5 * (a + b));
    if ((mid - centre).norm() < radius) out.push_back(e);
  }
  return out;
}

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

// The tooth an error names, or -1.
int error_tooth(const GearErrors& e) {
  for (const auto& f : e.flank_offsets)
    if (f.normal_offset_m != 0) return f.tooth;
  for (const auto& f : e.profile_slopes)
    if (f.slope_m != 0 && f.tooth >= 0) return f.tooth;
  for (const auto& f : e.pitch_errors)
    if (f.error_m != 0) return f.tooth;
  return -1;
}

}  // namespace

TrackedTooth tracked_tooth(const PlanetaryFeDef& def) {
  for (int k = 0; k < static_cast<int>(def.planet_gears.size()); ++k) {
    const GearSpec& g = def.planet_gears[static_cast<size_t>(k)];
    const int t = error_tooth(g.errors);
    if (t >= 0) return {k, t % g.teeth, true};
  }
  return {0, 0, false};
}

PlanetaryFeMeshes mesh_planetary(const PlanetaryFeDef& def) {
  if (!def.planet_gears.empty() && static_cast<int>(def.planet_gears.size()) != def.spec.planets)
    throw InputError("planetary FE: planet_gears must list one gear per planet (" +
                     std::to_string(def.spec.planets) + ")");
  PlanetaryFeMeshes m;
  m.sun = mesh_gear_outline(make_gear_outline(def.spec.sun), GearKind::External, def.sizing);
  m.ring = mesh_gear_outline(make_gear_outline(def.spec.ring), GearKind::Internal, def.sizing);
  for (int k = 0; k < def.spec.planets; ++k)
    m.planets.push_back(mesh_gear_outline(make_gear_outline(planet_gear(def, k)), GearKind::External, def.sizing));
  return m;
}

PlanetaryFePosition solve_position(const PlanetaryFeDef& def, const PlanetaryFeMeshes& meshes,
                                   double sun_turn_rad, const std::filesystem::path& work_dir) {
  const PlanetarySpec& ps = def.spec;
  const PlanetaryGeometry geo = analyse_planetary(ps);
  // Place the set and close its clearances with the rigid flank tables.
  const contact::FlankTable ts = flank_table_of(ps.sun), tr = flank_table_of(ps.ring);
  std::vector<contact::FlankTable> tp;
  for (int k = 0; k < ps.planets; ++k) tp.push_back(flank_table_of(planet_gear(def, k)));
  PlanetaryTables tables{&ts, {}, &tr};
  for (const auto& t : tp) tables.planets.push_back(&t);
  const PlanetaryPosition pos = place_closed(ps, geo, tables, sun_turn_rad);

  // Bodies: the sun drives, planets idle on held pins, the ring rim is fixed.
  const GearDimensions sd = make_gear_outline(ps.sun).dims, rd = make_gear_outline(ps.ring).dims;
  const GearDimensions pd = make_gear_outline(ps.planet).dims;
  const double band = kContactBand_modules * ps.sun.module_m;
  DeckDef deck;
  deck.bodies.push_back({"SUN", to_fe_mesh(meshes.sun.mesh), pos.sun.centre_m, pos.sun.angle_rad, FeSupport::Driving});
  for (int k = 0; k < ps.planets; ++k) {
    const auto& pp = pos.planets[static_cast<size_t>(k)];
    deck.bodies.push_back({"P" + std::to_string(k), to_fe_mesh(meshes.planets[static_cast<size_t>(k)].mesh),
                           pp.centre_m, pp.angle_rad, FeSupport::Idler});
  }
  deck.bodies.push_back({"RING", to_fe_mesh(meshes.ring.mesh), pos.ring.centre_m, pos.ring.angle_rad, FeSupport::Fixed});
  const int ring = ps.planets + 1;
  std::vector<std::vector<ToothedEdgeTag>> planet_tags;
  for (int k = 0; k < ps.planets; ++k)
    planet_tags.push_back(tag_toothed_edges(meshes.planets[static_cast<size_t>(k)].mesh, planet_gear(def, k),
                                            gear_dimensions(planet_gear(def, k))));
  std::vector<std::vector<int>> sun_mesh_teeth(static_cast<size_t>(ps.planets));
  // Contacts: sun (slave) on each planet, each planet (slave) on the ring.
  for (int k = 0; k < ps.planets; ++k) {
    const auto& pp = pos.planets[static_cast<size_t>(k)];
    const QuadMesh2& pm = meshes.planets[static_cast<size_t>(k)].mesh;
    // One contact pair per planet tooth within reach of the sun (the tooth as slave, the sun's
    // edges near this planet as master), so each tooth's force is read on its own.
    const auto sun_side = edges_near(meshes.sun.mesh, pos.sun, pp.centre_m, pd.tip_radius_m + band);
    const auto planet_side = edges_near(pm, pp, pos.sun.centre_m, sd.tip_radius_m + band);
    const auto& tags = planet_tags[static_cast<size_t>(k)];
    std::vector<int> teeth;
    for (const QuadEdge& e : planet_side) {
      const auto it = std::find(pm.toothed_edges.begin(), pm.toothed_edges.end(), e);
      teeth.push_back(tags[static_cast<size_t>(it - pm.toothed_edges.begin())].tooth);
    }
    std::vector<int> distinct = teeth;
    std::sort(distinct.begin(), distinct.end());
    distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
    for (int j : distinct) {
      std::vector<std::pair<int, int>> slave;
      for (std::size_t i = 0; i < planet_side.size(); ++i)
        if (teeth[i] == j) slave.push_back(planet_side[i]);
      deck.contacts.push_back({"SP" + std::to_string(k) + "T" + std::to_string(j), k + 1, 0, slave, sun_side});
      sun_mesh_teeth[static_cast<size_t>(k)].push_back(j);
    }
    std::vector<std::pair<int, int>> ring_side;
    const Eigen::Rotation2Dd rot(pp.angle_rad);
    for (const QuadEdge& e : pm.toothed_edges) {
      const auto [a, b] = edge_points(pm, e);
      if ((pp.centre_m + rot * (0.5 * (a + b))).norm() > rd.tip_radius_m - band) ring_side.push_back(e);
    }
    deck.contacts.push_back({"PR" + std::to_string(k), k + 1, ring, ring_side,
                             edges_near(meshes.ring.mesh, pos.ring, pp.centre_m, pd.tip_radius_m + band)});
  }
  // Root stresses of the tracked tooth and its two neighbours (which carry the planet's share
  // alone where a faulty tooth does not touch), both sides of each.
  const TrackedTooth tracked = tracked_tooth(def);
  const GearSpec& tg = planet_gear(def, tracked.planet);
  const GearDimensions tracked_dims = gear_dimensions(tg);
  struct RootSet {
    std::string name;
    int tooth;
    Flank side;
  };
  std::vector<RootSet> root_sets;
  for (int dt : {-1, 0, 1}) {
    const int tooth = ((tracked.tooth + dt) % tg.teeth + tg.teeth) % tg.teeth;
    for (Flank side : {Flank::Ccw, Flank::Cw}) {
      RootSet rs{"ROOT" + std::to_string(tooth) + (side == Flank::Ccw ? "C" : "W"), tooth, side};
      std::vector<int> els = root_elements(meshes.planets[static_cast<size_t>(tracked.planet)].mesh,
                                           planet_tags[static_cast<size_t>(tracked.planet)],
                                           tracked_dims, GearKind::External, tooth, side);
      if (els.empty())
        throw InputError("planetary FE: tooth " + std::to_string(tooth) + " of planet " +
                         std::to_string(tracked.planet) + " has no root elements in its mesh");
      deck.stress_sets.push_back({rs.name, tracked.planet + 1, std::move(els)});
      root_sets.push_back(rs);
    }
  }
  deck.thickness_m = ps.sun.face_width_m;
  deck.element_type = def.element_type;
  deck.friction = def.friction;
  deck.closing_rotation_rad = kClosingPress_m / sd.base_radius_m;
  deck.torque_N_m = def.sun_torque_N_m;
  deck.load_fractions = {kLowLoadFraction, 1.0};
  deck.idler_spring_N_m_per_rad = kIdlerSpring_N_m_per_rad;
  const Deck d = write_deck(deck);

  // Solve, unless this folder already holds a finished solve of the very same deck (a resumed
  // run): position.done records the solve's wall time once ccx has succeeded.
  std::filesystem::create_directories(work_dir);
  CcxRunResult run;
  run.dat_path = work_dir / "position.dat";
  run.log_path = work_dir / "position.log";
  bool reused = false;
  {
    std::ifstream old_deck(work_dir / "position.inp"), done(work_dir / "position.done");
    if (old_deck && done && std::filesystem::exists(run.dat_path)) {
      const std::string text((std::istreambuf_iterator<char>(old_deck)), std::istreambuf_iterator<char>());
      reused = text == d.text && static_cast<bool>(done >> run.wall_time_s);
    }
  }
  if (!reused) {
    std::filesystem::remove(work_dir / "position.done");
    std::ofstream(work_dir / "position.inp") << d.text;
    run = run_ccx({def.ccx, work_dir, "position"});
    std::ofstream(work_dir / "position.done") << std::setprecision(17) << run.wall_time_s << '\n';
  }

  // Results at the end of the low (time 2) and full (time 3) load stages.
  const auto blocks = read_dat(run.dat_path);
  auto rotation = [&](int body, double time) {
    for (const DatBlock& b : blocks)
      if (b.quantity == "displacements" && b.set == "NROT" && std::abs(b.time - time) < 1e-6)
        return b.rows.at(d.layout[static_cast<size_t>(body)].rotation_node).at(0);
    throw std::runtime_error("ccx results lack the rotations at time " + std::to_string(time) + " (" +
                             run.dat_path.string() + ")");
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
  const auto totals = read_contact_totals(run.dat_path);
  auto totals_of = [&](const std::string& slave, double time) -> const ContactTotals& {
    for (auto it = totals.rbegin(); it != totals.rend(); ++it)
      if (it->slave == slave && std::abs(it->time - time) < 1e-6) return *it;
    throw std::runtime_error("ccx results lack the contact force of " + slave + " at time " +
                             std::to_string(time) + " (" + run.dat_path.string() + ")");
  };
  auto force_vector = [&](const std::string& slave, double time) -> Eigen::Vector3d {
    const ContactTotals& t = totals_of(slave, time);
    return {t.force[0], t.force[1], t.force[2]};  // N in the deck too
  };
  auto force = [&](const std::string& slave, double time) { return force_vector(slave, time).norm(); };
  // The sun's force on a planet: the sum over its teeth's pairs.
  auto sun_force = [&](int k, double time) {
    Eigen::Vector3d f = Eigen::Vector3d::Zero();
    for (int j : sun_mesh_teeth[static_cast<size_t>(k)])
      f += force_vector("SSP" + std::to_string(k) + "T" + std::to_string(j), time);
    return f.norm();
  };
  const double rbs = sd.base_radius_m, rbp = pd.base_radius_m;
  auto secant = [](double dF, double approach) {
    return approach != 0 ? dF / approach : std::numeric_limits<double>::quiet_NaN();
  };
  for (int k = 0; k < ps.planets; ++k) {
    const std::string n = std::to_string(k);
    out.sun_planet_force_N.push_back(sun_force(k, 3.0));
    out.planet_ring_force_N.push_back(force("SPR" + n, 3.0));
    out.sun_planet_force_low_N.push_back(sun_force(k, 2.0));
    out.planet_ring_force_low_N.push_back(force("SPR" + n, 2.0));
    const double dp = out.planet_rotation_rad[k] - out.planet_rotation_low_rad[k];
    out.sun_planet_stiffness_N_per_m.push_back(
        secant(out.sun_planet_force_N[k] - out.sun_planet_force_low_N[k], rbs * (sun_full - sun_low) + rbp * dp));
    out.planet_ring_stiffness_N_per_m.push_back(
        secant(out.planet_ring_force_N[k] - out.planet_ring_force_low_N[k], -rbp * dp));
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
  out.te_elastic_rad = dm > 0 ? (sun_full - sun_low) / dm * def.sun_torque_N_m
                              : std::numeric_limits<double>::quiet_NaN();
  out.te_loaded_rad = out.te_geometric_rad + out.te_elastic_rad;
  for (int k = 0; k < ps.planets; ++k) {
    std::vector<std::pair<int, double>> per_tooth;
    for (int j : sun_mesh_teeth[static_cast<size_t>(k)])
      per_tooth.emplace_back(j, force("SSP" + std::to_string(k) + "T" + std::to_string(j), 3.0));
    out.sun_mesh_tooth_force_N.push_back(std::move(per_tooth));
  }
  out.tracked = tracked;
  for (std::size_t i = 0; i < root_sets.size(); ++i) {
    const std::string& set = root_sets[i].name;
    auto stress_at = [&](double time) -> const DatBlock& {
      for (const DatBlock& b : blocks)
        if (b.quantity == "stresses" && b.set == set && std::abs(b.time - time) < 1e-6) return b;
      throw std::runtime_error("ccx results lack the stresses of " + set + " at time " + std::to_string(time) +
                               " (" + run.dat_path.string() + ")");
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
  out.wall_time_s = run.wall_time_s;
  return out;
}

std::vector<double> sweep_turns(const PlanetaryFeDef& def, int positions_per_mesh, double mesh_periods) {
  if (positions_per_mesh < 1)
    throw InputError("planetary FE: positions_per_mesh must be at least 1, got " + std::to_string(positions_per_mesh));
  if (!(mesh_periods > 0) || !std::isfinite(mesh_periods))
    throw InputError("planetary FE: mesh_periods must be a positive number of mesh periods");
  const PlanetarySpec& ps = def.spec;
  const PlanetaryGeometry geo = analyse_planetary(ps);
  const double zs = ps.sun.teeth, zp = ps.planet.teeth;
  const TrackedTooth tracked = tracked_tooth(def);
  const PlanetPlacement& p0 = geo.placements.at(static_cast<size_t>(tracked.planet));
  // Planet 0 turns −φ z_s/z_p with the sun's turn φ; its tooth 0 faces the sun (polar angle
  // carrier_angle + π) once per planet revolution, i.e. every 2π z_p/z_s of φ.
  const double period = 2.0 * std::numbers::pi * zp / zs;
  // The flank the sun loads (sun driving counter-clockwise) passes the pitch point a quarter of a
  // mesh period later: half the tooth thickness at the pitch circle, π/(2 z_p) of planet turn,
  // is π/(2 z_s) of sun turn (checked with the rigid closing of a faulty tooth 0: its extra
  // closing spans +0.125…+0.375 of a mesh period after the centre-line passage).
  double centre = (p0.spin_angle_rad + planet_gear(def, tracked.planet).tooth0_angle_rad +
                   tracked.tooth * 2.0 * std::numbers::pi / zp - p0.carrier_angle_rad - std::numbers::pi) *
                      zp / zs +
                  std::numbers::pi / (2.0 * zs);
  centre = std::fmod(centre, period);
  if (centre < 0) centre += period;
  const int n = std::max(1, static_cast<int>(std::lround(positions_per_mesh * mesh_periods)));
  const double step = 2.0 * std::numbers::pi / zs / positions_per_mesh;
  std::vector<double> turns;
  for (int j = 0; j < n; ++j) turns.push_back(centre + (j - 0.5 * n) * step);
  return turns;
}

std::vector<PlanetaryFePosition> solve_positions(
    const PlanetaryFeDef& def, const PlanetaryFeMeshes& meshes, const std::vector<double>& turns_rad,
    const std::filesystem::path& work_dir, int jobs,
    const std::function<void(std::size_t, const PlanetaryFePosition&)>& on_done) {
  if (jobs < 1) throw InputError("planetary FE: jobs must be at least 1, got " + std::to_string(jobs));
  std::vector<PlanetaryFePosition> out(turns_rad.size());
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr first_error;
  std::mutex mutex;
  auto worker = [&] {
    for (;;) {
      if (failed) return;
      const std::size_t i = next++;
      if (i >= turns_rad.size()) return;
      char name[32];
      std::snprintf(name, sizeof name, "pos_%03zu", i);
      try {
        PlanetaryFePosition p = solve_position(def, meshes, turns_rad[i], work_dir / name);
        std::lock_guard<std::mutex> lock(mutex);
        out[i] = p;
        if (on_done) on_done(i, out[i]);
      } catch (...) {
        std::lock_guard<std::mutex> lock(mutex);
        if (!first_error) first_error = std::current_exception();
        failed = true;
        return;
      }
    }
  };
  std::vector<std::thread> threads;
  const int n = std::min<int>(jobs, static_cast<int>(turns_rad.size()));
  for (int t = 0; t < n; ++t) threads.emplace_back(worker);
  for (auto& t : threads) t.join();
  if (first_error) std::rethrow_exception(first_error);
  return out;
}

}  // namespace gearsim::fe
