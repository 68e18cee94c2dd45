// Suite named gear_mesher so `ctest -R gear_mesher` selects it.
// Quad meshes of the paper's gears (gmsh): the mesh covers the outline's area, every element is
// a valid counter-clockwise quad, boundary nodes sit on the outline, element sizes follow the
// sizing, a 43 µm flank error shows up on that flank only, and meshing is deterministic.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "core/errors.hpp"
#include "geometry/gear_profile.hpp"
#include "fe/gear_mesh_regions.hpp"
#include "fe/gear_mesher.hpp"
#include "fe/outline_resample.hpp"
#include "tests/support/gear_specs.hpp"
#include "tests/support/outline_probe.hpp"
#include "geometry/constants.hpp"

namespace gearsim::fe {
namespace test_gear_mesher {

using Eigen::Vector2d;
using gearsim::constants::kPi;
constexpr double kFlank = 0.4e-3;  // m, the default flank element size

// The paper's gears (assets/specs/paper_gearset.yaml): sun 24 / bore 8 mm, planet 36 / bore
// 10 mm, ring 96 / rim 110 mm; the faulty planet has 43 µm removed from tooth 0's Ccw flank.
GearSpec sun() { return test::external_gear(24, 8e-3); }
GearSpec planet() { return test::external_gear(36, 10e-3); }
GearSpec ring() { return test::internal_gear(96, 110e-3); }
GearSpec faulty_planet() {
  GearSpec s = planet();
  s.errors.flank_offsets.push_back({0, Flank::Ccw, -43e-6});
  return s;
}

const Polygon2& toothed_loop(const GearOutline& g, GearKind kind) {
  return kind == GearKind::External ? g.outline.outer : g.outline.holes.front();
}

// Meshing takes 0.1–0.6 s per gear: each (gear, sizing) is meshed once per test run.
struct Case {
  GearSpec spec;
  GearOutline outline;
  GearMesh mesh;
};
const Case& meshed(const std::string& which, bool subdivide = false) {
  static std::map<std::string, Case> cache;
  const std::string key = which + (subdivide ? "/split" : "");
  auto it = cache.find(key);
  if (it != cache.end()) return it->second;
  Case c;
  c.spec = which == "sun" ? sun() : which == "planet" ? planet() : which == "ring" ? ring() : faulty_planet();
  c.outline = make_gear_outline(c.spec);
  MeshSizingDef sizing;
  sizing.subdivide = subdivide;
  c.mesh = mesh_gear_outline(c.outline, c.spec.kind, sizing);
  return cache.emplace(key, std::move(c)).first->second;
}

double edge_length(const QuadMesh2& m, QuadEdge e) {
  const auto [a, b] = edge_points(m, e);
  return (b - a).norm();
}

TEST(gear_mesher, MeshAreaEqualsTheOutlineArea) {
  for (const char* g : {"sun", "planet", "ring"}) {
    const Case& c = meshed(g);
    // Boundary chords of 0.4 mm across the root fillets (ρ = 0.38 mm, sagitta ≈ h²/8ρ ≈ 50 µm)
    // add material, chords across tips, flanks and the 2 mm rim segments remove a little;
    // measured +0.57 % (sun), +0.31 % (planet), +0.08 % (ring). 1 % bounds that.
    const double a = area(c.outline.outline);
    EXPECT_NEAR(mesh_area(c.mesh.mesh) / a, 1.0, 0.01) << g;
  }
}

TEST(gear_mesher, QuadsTileTheBoundaryPolygonExactly) {
  // The quads neither overlap nor leave gaps: their areas add up to the area enclosed by the
  // boundary edges (relative 1e-12: rounding of ~1e4 shoelace sums only).
  for (const char* g : {"sun", "planet", "ring"}) {
    const QuadMesh2& m = meshed(g).mesh.mesh;
    double enclosed = 0.0;  // Σ over boundary edges of x_a·y_b − x_b·y_a, each edge as the quad runs it
    for (const auto* list : {&m.toothed_edges, &m.inner_edges, &m.outer_edges})
      for (const QuadEdge& e : *list) {
        const auto [a, b] = edge_points(m, e);
        enclosed += 0.5 * (a.x() * b.y() - b.x() * a.y());
      }
    EXPECT_NEAR(mesh_area(m) / enclosed, 1.0, 1e-12) << g;
  }
}

TEST(gear_mesher, AllElementsAreValidCounterClockwiseQuads) {
  for (const char* g : {"sun", "planet", "ring"}) {
    const GearMesh& gm = meshed(g).mesh;
    EXPECT_FALSE(gm.subdivided) << g << ": Blossom left triangles";
    for (int q = 0; q < static_cast<int>(gm.mesh.quads.size()); ++q) ASSERT_GT(quad_area(gm.mesh, q), 0.0) << g;
    // Measured 0.60–0.62 (interior angles 42°–143°); 0.4 (angles within 24°–156°) is a common
    // acceptance limit for linear quads and leaves room for other gmsh builds.
    EXPECT_GT(gm.quality.min_scaled_jacobian, 0.4) << g;
    EXPECT_GT(gm.quality.min_angle_rad, 24 * kPi / 180) << g;
    EXPECT_LT(gm.quality.max_angle_rad, 156 * kPi / 180) << g;
  }
}

TEST(gear_mesher, BoundaryNodesLieOnTheOutline) {
  for (const char* g : {"sun", "planet", "ring"}) {
    const Case& c = meshed(g);
    const QuadMesh2& m = c.mesh.mesh;
    // Nodes are outline vertices or points on its chords: distance ~1e-18 m; 1 µm is the bound
    // asked of the FE model (the flank errors are tens of µm).
    const Polygon2& teeth = toothed_loop(c.outline, c.spec.kind);
    for (const QuadEdge& e : m.toothed_edges) ASSERT_LT(test::distance_to_boundary(teeth, edge_points(m, e).first), 1e-6) << g;
    // Bore and rim nodes on their circles within the outline's 0.5 µm chordal deviation.
    for (int n : m.bore_nodes) ASSERT_NEAR(m.nodes[n].norm(), c.spec.bore_diameter_m / 2, 1e-6) << g;
    for (int n : m.rim_nodes) ASSERT_NEAR(m.nodes[n].norm(), c.spec.rim_diameter_m / 2, 1e-6) << g;
  }
}

TEST(gear_mesher, BoundaryGroupsMatchTheGearKind) {
  const QuadMesh2& p = meshed("planet").mesh.mesh;
  EXPECT_FALSE(p.toothed_edges.empty());
  EXPECT_EQ(p.inner_edges.size(), p.bore_nodes.size());  // a closed loop: as many edges as nodes
  EXPECT_TRUE(p.outer_edges.empty() && p.rim_nodes.empty());
  const QuadMesh2& r = meshed("ring").mesh.mesh;
  EXPECT_FALSE(r.toothed_edges.empty());
  EXPECT_EQ(r.outer_edges.size(), r.rim_nodes.size());
  EXPECT_TRUE(r.inner_edges.empty() && r.bore_nodes.empty());
  // The ring's toothed loop is its hole: its nodes lie between the tip and root circles.
  for (const QuadEdge& e : r.toothed_edges) {
    const double rad = edge_points(r, e).first.norm();
    ASSERT_GT(rad, 47e-3 - 1e-6);  // tip circle r = 48 − 1 mm
    ASSERT_LT(rad, 49.25e-3 + 1e-6);  // root circle r = 48 + 1.25 mm
  }
}

// Distance from point p to the segment a–b.
double to_segment(const Vector2d& p, const Vector2d& a, const Vector2d& b) {
  const Vector2d ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (p - (a + t * ab)).norm();
}

TEST(gear_mesher, ToothedEdgesFollowTheFlankSizeAndTheSagittaLimit) {
  const MeshSizingDef sizing;
  // The sharpest curve of the paper's outlines: root fillets of radius 0.38 m.
  const double shortest = std::sqrt(8.0 * 0.38e-3 * sizing.max_sagitta_m);
  for (const char* g : {"sun", "planet", "ring"}) {
    const Case& c = meshed(g);
    const QuadMesh2& m = c.mesh.mesh;
    // Edges: the flank size on straight-ish runs (equal arc lengths snapped to outline vertices
    // within 20 %), shorter where the outline curves, never shorter than half the fillets'
    // √(8 ρ s) (snapping and grading included).
    for (const QuadEdge& e : m.toothed_edges) {
      ASSERT_GT(edge_length(m, e), 0.5 * shortest) << g;
      ASSERT_LT(edge_length(m, e), 1.5 * kFlank) << g;
    }
    // Every outline vertex (an exact curve point, 0.5 µm chordal tolerance) lies within the
    // sagitta limit of the mesh boundary: the limit bounds the local spacing, and snapping to
    // vertices stretches an edge by up to 20 % (sagitta ×1.44). Measured 6.1–7.0 µm for 5 µm.
    std::vector<std::pair<Vector2d, Vector2d>> edges;
    for (const QuadEdge& e : m.toothed_edges) edges.push_back(edge_points(m, e));
    double worst = 0.0;
    for (const Vector2d& p : toothed_loop(c.outline, c.spec.kind).points) {
      double d = 1e9;
      for (const auto& [a, b] : edges) d = std::min(d, to_segment(p, a, b));
      worst = std::max(worst, d);
    }
    EXPECT_LT(worst, 1.5 * sizing.max_sagitta_m) << g;
  }
}

TEST(gear_mesher, WithoutTheSagittaLimitFilletChordsCutFarIntoTheToothSpace) {
  // The defect the limit removes: at a uniform 0.4 mm a chord across a 0.38 mm fillet sits tens
  // of µm off the curve (c²/(8ρ) = 53 µm for a full 0.4 mm chord).
  const Case& c = meshed("ring");
  const ArcPolygon poly = make_arc_polygon(toothed_loop(c.outline, c.spec.kind));
  const double uniform = max_edge_sagitta(poly, resample_loop(poly, kFlank));
  const double limited = max_edge_sagitta(poly, resample_loop(poly, kFlank, 5e-6));
  EXPECT_GT(uniform, 20e-6);
  EXPECT_LT(limited, 1.5 * 5e-6);
}

TEST(gear_mesher, CoreElementsAreCoarse) {
  for (const char* g : {"sun", "planet", "ring"}) {
    const Case& c = meshed(g);
    const QuadMesh2& m = c.mesh.mesh;
    // Mean edge of quads lying wholly past the 3 mm transition (centroid 3.5 mm from the root
    // circle): the core size 2 mm; measured 1.6–1.8 mm (Blossom's quads of size-h triangles
    // have sides a little below h). Between 0.7 and 1.2 times the core size.
    const double root = c.outline.dims.root_radius_m;
    double sum = 0.0;
    int n = 0;
    for (const auto& q : m.quads) {
      const Vector2d centre = 0.25 * (m.nodes[q[0]] + m.nodes[q[1]] + m.nodes[q[2]] + m.nodes[q[3]]);
      const double depth = c.spec.kind == GearKind::External ? root - centre.norm() : centre.norm() - root;
      if (depth < 3.5e-3) continue;
      for (int e = 0; e < 4; ++e) sum += (m.nodes[q[(e + 1) % 4]] - m.nodes[q[e]]).norm();
      n += 4;
    }
    ASSERT_GT(n, 0) << g;
    EXPECT_GT(sum / n, 0.7 * 2e-3) << g;
    EXPECT_LT(sum / n, 1.2 * 2e-3) << g;
  }
}

TEST(gear_mesher, FlankErrorMovesThatFlankOnlyAndByItsSize) {
  const Case& healthy = meshed("planet");
  const Case& faulty = meshed("faulty");
  const Polygon2& healthy_loop = healthy.outline.outline.outer;
  const GearDimensions& d = faulty.outline.dims;
  const auto tags = tag_toothed_edges(faulty.mesh.mesh, faulty.spec, d);
  const QuadMesh2& m = faulty.mesh.mesh;
  int on_fault = 0;
  for (std::size_t i = 0; i < tags.size(); ++i) {
    const Vector2d p = edge_points(m, m.toothed_edges[i]).first;
    const double dist = test::distance_to_boundary(healthy_loop, p);
    const double r = p.norm();
    const bool fault_flank = tags[i].tooth == 0 && tags[i].side == Flank::Ccw;
    if (fault_flank && r > d.form_radius_m + 0.1e-3 && r < d.tip_radius_m - 0.1e-3) {
      // Mid-flank: the flank is the healthy involute rotated by 43 µm / r_b, a parallel curve
      // 43 µm away. 1 µm: the nodes' 0.5 µm chordal deviation on each of the two outlines.
      EXPECT_NEAR(dist, 43e-6, 1e-6) << "r = " << r;
      ++on_fault;
    } else if (!fault_flank) {
      // Everywhere else the faulty mesh's boundary lies on the healthy outline.
      ASSERT_LT(dist, 1e-6) << "tooth " << tags[i].tooth << " r = " << r;
    }
  }
  // The active flank (form 17.1 mm to tip 19 mm, ≈ 2 mm of involute) carries ≈ 5 nodes at 0.4 mm.
  EXPECT_GE(on_fault, 3);
}

// The root elements of one side of a tooth own the fillet and root-land edges between the form
// and root circles on that side of the tooth's centre line, within half a pitch of it.
TEST(gear_mesher, RootElementsLieInTheFilletOfTheirSide) {
  const Case& c = meshed("planet");
  const auto tags = tag_toothed_edges(c.mesh.mesh, c.spec, c.outline.dims);
  const GearDimensions& d = c.outline.dims;
  const double pitch = 2 * std::numbers::pi / c.spec.teeth;
  for (int k : {0, 7}) {
    std::vector<int> sides[2];
    for (int s = 0; s < 2; ++s) {
      const Flank f = s == 0 ? Flank::Ccw : Flank::Cw;
      sides[s] = root_elements(c.mesh.mesh, tags, d, GearKind::External, k, f);
      // A 0.38 mm fillet and half a root land at ≤ 0.4 mm spacing: at least 3 boundary quads.
      EXPECT_GE(sides[s].size(), 3u) << k;
      for (int q : sides[s]) {
        Vector2d centre = Vector2d::Zero();
        for (int n : c.mesh.mesh.quads[static_cast<size_t>(q)]) centre += c.mesh.mesh.nodes[static_cast<size_t>(n)] / 4;
        // Centres lie below the form circle and above the root circle less one element.
        EXPECT_LT(centre.norm(), d.form_radius_m) << k;
        EXPECT_GT(centre.norm(), d.root_radius_m - 0.4e-3) << k;
        double off = std::atan2(centre.y(), centre.x()) - c.spec.tooth0_angle_rad - k * pitch;
        off = std::remainder(off, 2 * std::numbers::pi);
        EXPECT_LT(std::abs(off), 0.5 * pitch + 1e-3) << k;
        EXPECT_EQ(off > 0, f == Flank::Ccw) << "tooth " << k << " quad " << q << " offset " << off;
      }
    }
    for (int q : sides[0]) EXPECT_EQ(std::count(sides[1].begin(), sides[1].end(), q), 0) << q;
  }
}

TEST(gear_mesher, ToothTagsSelectEachFlankOfEachTooth) {
  const Case& c = meshed("faulty");
  const auto tags = tag_toothed_edges(c.mesh.mesh, c.spec, c.outline.dims);
  ASSERT_EQ(tags.size(), c.mesh.mesh.toothed_edges.size());
  // Every tooth has flank edges on both sides; the selection of tooth 0's Ccw flank holds exactly
  // the edges whose nodes the 43 µm error moved off the healthy outline.
  for (int k = 0; k < c.spec.teeth; ++k)
    for (Flank f : {Flank::Ccw, Flank::Cw}) EXPECT_GE(select_tooth_edges(c.mesh.mesh, tags, {{k}, true, true, f}).size(), 3u) << k;
  const Polygon2& healthy = meshed("planet").outline.outline.outer;
  for (const QuadEdge& e : select_tooth_edges(c.mesh.mesh, tags, {{0}, true, true, Flank::Ccw})) {
    const auto [a, b] = edge_points(c.mesh.mesh, e);
    // At least one end of each flank edge is off the healthy flank (the other may be the corner
    // shared with the tip land or the fillet, where the offset shrinks).
    EXPECT_GT(std::max(test::distance_to_boundary(healthy, a), test::distance_to_boundary(healthy, b)), 20e-6);
  }
}

TEST(gear_mesher, SameInputGivesTheSameMeshBitForBit) {
  const Case& c = meshed("sun");
  const GearMesh again = mesh_gear_outline(c.outline, c.spec.kind, MeshSizingDef{});
  ASSERT_EQ(again.mesh.nodes.size(), c.mesh.mesh.nodes.size());
  ASSERT_EQ(again.mesh.quads, c.mesh.mesh.quads);
  for (std::size_t i = 0; i < again.mesh.nodes.size(); ++i) ASSERT_EQ(again.mesh.nodes[i], c.mesh.mesh.nodes[i]);
  EXPECT_EQ(again.mesh.toothed_edges, c.mesh.mesh.toothed_edges);
  EXPECT_EQ(again.mesh.inner_edges, c.mesh.mesh.inner_edges);
}

TEST(gear_mesher, SubdividedMeshIsAllQuadsWithBoundaryOnTheOutline) {
  for (const char* g : {"planet", "ring"}) {
    const Case& c = meshed(g, /*subdivide=*/true);
    const QuadMesh2& m = c.mesh.mesh;
    EXPECT_TRUE(c.mesh.subdivided);
    // Valid quads (measured min scaled Jacobian 0.05 on the ring, 0.28 on the planet: the split
    // is the fallback, coarser in shape than direct recombination).
    EXPECT_GT(c.mesh.quality.min_scaled_jacobian, 0.0) << g;
    const Polygon2& teeth = toothed_loop(c.outline, c.spec.kind);
    for (const QuadEdge& e : m.toothed_edges) {
      // New boundary midpoints are placed on the outline too (1 µm as above) ...
      ASSERT_LT(test::distance_to_boundary(teeth, edge_points(m, e).first), 1e-6) << g;
      // ... and the split of 0.8 mm edges keeps the 0.4 mm flank size (at most 1.5×; shorter
      // where the sagitta limit shortens them, never below half the fillets' √(8 ρ s)).
      ASSERT_GT(edge_length(m, e), 0.5 * std::sqrt(8.0 * 0.38e-3 * MeshSizingDef{}.max_sagitta_m)) << g;
      ASSERT_LT(edge_length(m, e), 1.5 * kFlank) << g;
    }
    EXPECT_NEAR(mesh_area(m) / area(c.outline.outline), 1.0, 0.01) << g;
  }
}

TEST(gear_mesher, GradingFollowsTheRadialRule) {
  const Case& c = meshed("planet");
  const MeshSizingDef s;
  const double root = c.outline.dims.root_radius_m;
  const auto size = [&](double r) { return mesh_size_at_radius(c.outline, GearKind::External, s, r); };
  EXPECT_DOUBLE_EQ(size(root + 1e-3), s.flank_size_m);  // in the teeth
  EXPECT_DOUBLE_EQ(size(root - s.transition_m / 2), 0.5 * (s.flank_size_m + s.core_size_m));  // half way
  EXPECT_DOUBLE_EQ(size(root - 2 * s.transition_m), s.core_size_m);  // in the core
  const Case& r = meshed("ring");
  EXPECT_DOUBLE_EQ(mesh_size_at_radius(r.outline, GearKind::Internal, s, r.outline.dims.root_radius_m + 4e-3),
                   s.core_size_m);  // internal: the core lies outward
}

TEST(gear_mesher, RejectsBadSizingAndMismatchedOutlines) {
  const Case& c = meshed("planet");
  auto with = [](auto set) {
    MeshSizingDef s;
    set(s);
    return s;
  };
  EXPECT_THROW(mesh_gear_outline(c.outline, GearKind::External, with([](auto& s) { s.flank_size_m = 0; })), InputError);
  EXPECT_THROW(mesh_gear_outline(c.outline, GearKind::External, with([](auto& s) { s.flank_size_m = NAN; })), InputError);
  EXPECT_THROW(mesh_gear_outline(c.outline, GearKind::External, with([](auto& s) { s.core_size_m = 0.1e-3; })), InputError);
  EXPECT_THROW(mesh_gear_outline(c.outline, GearKind::External, with([](auto& s) { s.transition_m = -1e-3; })), InputError);
  EXPECT_THROW(mesh_gear_outline(c.outline, GearKind::External, with([](auto& s) { s.flank_size_m = 1e-6; })), InputError);
  try {
    mesh_gear_outline(c.outline, GearKind::External, with([](auto& s) { s.flank_size_m = -1; }));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("flank_size_m"), std::string::npos) << e.what();
  }
  // A solid external outline (no hole) is fine for External, not for Internal.
  GearOutline solid = c.outline;
  solid.outline.holes.clear();
  EXPECT_THROW(mesh_gear_outline(solid, GearKind::Internal, MeshSizingDef{}), InputError);
}

}  // namespace test_gear_mesher
}  // namespace gearsim::fe
