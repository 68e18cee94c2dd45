// Quadrilateral finite-element meshes of a gear's planar outline (for CalculiX plane stress,
// CPS4R), made with Gmsh's C++ API: the boundary resampled at the flank element size with every
// node on the outline, Delaunay triangles (gmsh algorithm kGmshAlgorithm2D = 5) of a radially
// graded size recombined into quads by Blossom. Not a deck writer, and not the tooth/flank bookkeeping (gear_mesh_regions.hpp).
#pragma once

#include "geometry/gear_profile.hpp"
#include "geometry/gear_spec.hpp"
#include "fe/constants.hpp"
#include "fe/quad_mesh.hpp"

namespace gearsim::fe {

// How fine the mesh is, where. The size is flank_size_m on the toothed loop and in the teeth
// (beyond the root circle) and grows linearly to core_size_m over transition_m from the root
// circle into the body: inward for external gears, outward for internal ones.
struct MeshSizingDef {
  double flank_size_m = kDefaultFlankElementSize_m;  // m, normally 0.4 mm (paper's converged size)
  double core_size_m = kDefaultCoreElementSize_m;  // m, normally 2 mm; ≥ flank_size_m
  double transition_m = kDefaultSizeTransition_m;  // m, normally 3 mm; ≥ 0
  // Largest distance of a toothed-loop edge from the true outline, m (default kDefaultMaxSagitta_m,
  // 5 µm; paper_te_loaded.yaml gives 1 µm; 0 turns the limit off and keeps flank_size_m along the
  // whole loop). Edges shorten where the outline
  // curves (flanks near the base circle, root fillets): see resample_loop.
  double max_sagitta_m = kDefaultMaxSagitta_m;
  // Mesh at twice the size and split every element into quads (quads into 4, triangles into 3),
  // with new boundary nodes placed on the outline. Normally off: Blossom already returns only
  // quads, and it is used anyway when Blossom leaves a triangle.
  bool subdivide = false;
};

struct GearMesh {
  QuadMesh2 mesh;
  QuadMeshQuality quality;
  bool subdivided = false;  // whether the split described in MeshSizingDef::subdivide was used
};

// Element size at radius r from the gear centre, m (the sizing rule above).
double mesh_size_at_radius(const GearOutline& gear, GearKind kind, const MeshSizingDef& sizing, double radius_m);

// Meshes the outline. Throws InputError naming the field for a bad sizing or an outline that does
// not match `kind`, and InputError quoting gmsh's message when gmsh fails. Deterministic: the
// same input gives the same mesh, bit for bit. Serialised: gmsh is one global state, so calls
// from several threads run one at a time.
GearMesh mesh_gear_outline(const GearOutline& gear, GearKind kind, const MeshSizingDef& sizing);

}  // namespace gearsim::fe
