// One position of the planetary FE solve as a CalculiX deck: the set placed and closed, the
// bodies with their supports, a contact pair per planet tooth near the sun and per planet on the
// ring, the tracked tooth's root-stress sets, the loads. Not the solve and not the results
// (planetary_fe.cpp, planetary_fe_results.cpp).
#include <Eigen/Geometry>
#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "core/errors.hpp"
#include "fe/constants.hpp"
#include "fe/gear_mesh_regions.hpp"
#include "fe/planetary_fe_detail.hpp"

namespace gearsim::fe::planetary_detail {
namespace {

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
std::vector<std::pair<int, int>> edges_near(const QuadMesh2& q, const contact::PlanarPose& pose, const Eigen::Vector2d& centre,
                                            double radius) {
  std::vector<std::pair<int, int>> out;
  const Eigen::Rotation2Dd rot(pose.angle_rad);
  for (const QuadEdge& e : q.toothed_edges) {
    const auto [a, b] = edge_points(q, e);
    const Eigen::Vector2d mid = pose.centre_m + rot * (0.5 * (a + b));
    if ((mid - centre).norm() < radius) out.push_back(e);
  }
  return out;
}

// The set placed at sun_turn_rad, its clearances closed with the rigid flank tables.
PlanetaryPosition placed_set(const PlanetaryFeDef& def, double sun_turn_rad) {
  const PlanetarySpec& ps = def.spec;
  const PlanetaryGeometry geo = analyse_planetary(ps);
  // Place the set and close its clearances with the rigid flank tables.
  const contact::FlankTable ts = flank_table_of(ps.sun), tr = flank_table_of(ps.ring);
  std::vector<contact::FlankTable> tp;
  for (int k = 0; k < ps.planets; ++k) tp.push_back(flank_table_of(planet_gear(def, k)));
  PlanetaryTables tables{&ts, {}, &tr};
  for (const auto& t : tp) tables.planets.push_back(&t);
  return place_closed(ps, geo, tables, sun_turn_rad);
}

// Bodies: the sun drives, planets idle on held pins, the ring rim is fixed.
void add_bodies(DeckDef& deck, const PlanetarySpec& ps, const PlanetaryPosition& pos, const PlanetaryFeMeshes& meshes) {
  deck.bodies.push_back({"SUN", to_fe_mesh(meshes.sun.mesh), pos.sun.centre_m, pos.sun.angle_rad, FeSupport::Driving});
  for (int k = 0; k < ps.planets; ++k) {
    const auto& pp = pos.planets[static_cast<size_t>(k)];
    deck.bodies.push_back(
        {"P" + std::to_string(k), to_fe_mesh(meshes.planets[static_cast<size_t>(k)].mesh), pp.centre_m, pp.angle_rad, FeSupport::Idler});
  }
  deck.bodies.push_back({"RING", to_fe_mesh(meshes.ring.mesh), pos.ring.centre_m, pos.ring.angle_rad, FeSupport::Fixed});
}

// Contacts: each planet tooth near the sun (slave) on the sun (master), one pair per tooth, and
// each planet (slave) on the ring (master); sets p.sun_mesh_teeth.
void add_contacts(PositionDeck& p, const PlanetaryFeDef& def, const PlanetaryFeMeshes& meshes,
                  const std::vector<std::vector<ToothedEdgeTag>>& planet_tags, double band) {
  const PlanetarySpec& ps = def.spec;
  const PlanetaryPosition& pos = p.pos;
  const GearDimensions &sd = p.sun_dims, &rd = p.ring_dims, &pd = p.planet_dims;
  DeckDef& deck = p.deck;
  const int ring = ps.planets + 1;
  std::vector<std::vector<int>>& sun_mesh_teeth = p.sun_mesh_teeth;
  sun_mesh_teeth.resize(static_cast<size_t>(ps.planets));
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
    deck.contacts.push_back(
        {"PR" + std::to_string(k), k + 1, ring, ring_side, edges_near(meshes.ring.mesh, pos.ring, pp.centre_m, pd.tip_radius_m + band)});
  }
}

// Root stresses of the tracked tooth and its two neighbours (which carry the planet's share
// alone where a faulty tooth does not touch), both sides of each; sets p.tracked and p.root_sets.
void add_root_sets(PositionDeck& p, const PlanetaryFeDef& def, const PlanetaryFeMeshes& meshes,
                   const std::vector<std::vector<ToothedEdgeTag>>& planet_tags) {
  DeckDef& deck = p.deck;
  p.tracked = tracked_tooth(def);
  const TrackedTooth& tracked = p.tracked;
  const GearSpec& tg = planet_gear(def, tracked.planet);
  const GearDimensions tracked_dims = gear_dimensions(tg);
  std::vector<RootSet>& root_sets = p.root_sets;
  for (int dt : {-1, 0, 1}) {
    const int tooth = ((tracked.tooth + dt) % tg.teeth + tg.teeth) % tg.teeth;
    for (Flank side : {Flank::Ccw, Flank::Cw}) {
      RootSet rs{"ROOT" + std::to_string(tooth) + (side == Flank::Ccw ? "C" : "W"), tooth, side};
      std::vector<int> els = root_elements(meshes.planets[static_cast<size_t>(tracked.planet)].mesh,
                                           planet_tags[static_cast<size_t>(tracked.planet)], tracked_dims, GearKind::External, tooth, side);
      if (els.empty())
        throw InputError("planetary FE: tooth " + std::to_string(tooth) + " of planet " + std::to_string(tracked.planet) +
                         " has no root elements in its mesh");
      deck.stress_sets.push_back({rs.name, tracked.planet + 1, std::move(els)});
      root_sets.push_back(rs);
    }
  }
}

}  // namespace

PositionDeck build_position_deck(const PlanetaryFeDef& def, const PlanetaryFeMeshes& meshes, double sun_turn_rad) {
  const PlanetarySpec& ps = def.spec;
  PositionDeck p;
  p.pos = placed_set(def, sun_turn_rad);
  // The bodies, then the contact pairs and root-stress sets on their meshes, then the loads.
  p.sun_dims = make_gear_outline(ps.sun).dims;
  p.ring_dims = make_gear_outline(ps.ring).dims;
  p.planet_dims = make_gear_outline(ps.planet).dims;
  const double band = kContactBand_modules * ps.sun.module_m;
  add_bodies(p.deck, ps, p.pos, meshes);
  std::vector<std::vector<ToothedEdgeTag>> planet_tags;
  for (int k = 0; k < ps.planets; ++k)
    planet_tags.push_back(
        tag_toothed_edges(meshes.planets[static_cast<size_t>(k)].mesh, planet_gear(def, k), gear_dimensions(planet_gear(def, k))));
  add_contacts(p, def, meshes, planet_tags, band);
  add_root_sets(p, def, meshes, planet_tags);
  DeckDef& deck = p.deck;
  const GearDimensions& sd = p.sun_dims;
  deck.thickness_m = ps.sun.face_width_m;
  deck.element_type = def.element_type;
  deck.friction = def.friction;
  deck.closing_rotation_rad = kClosingPress_m / sd.base_radius_m;
  deck.torque_N_m = def.sun_torque_N_m;
  deck.load_fractions = {kLowLoadFraction, 1.0};
  deck.idler_spring_N_m_per_rad = kIdlerSpring_N_m_per_rad;
  p.written = write_deck(deck);
  return p;
}

}  // namespace gearsim::fe::planetary_detail
