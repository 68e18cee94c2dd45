// Mass properties of a closed triangle mesh of uniform density: volume, mass, centre of mass,
// inertia tensor about the centre of mass, principal moments and axes. Exact for the polyhedron
// (divergence theorem: the solid is summed as signed tetrahedra, one per face, from a reference
// point near the centroid, as in Tonon 2004, J. Math. Stat. 1(1)).
// Not a validity check: the mesh must bound a solid (see require_valid_solid in
// mesh_validate.hpp); an open or self-intersecting mesh gives numbers without meaning.
#pragma once

#include <Eigen/Core>

#include "geometry/mesh.hpp"

namespace gearsim {

struct MassProperties {
  double volume_m3 = 0.0;
  double mass_kg = 0.0;
  Eigen::Vector3d centre_of_mass_m = Eigen::Vector3d::Zero();  // in the mesh frame
  // About the centre of mass, mesh axes, full tensor: I_xx = ∫(y²+z²) dm, I_xy = −∫xy dm.
  Eigen::Matrix3d inertia_com_kg_m2 = Eigen::Matrix3d::Zero();
  // Eigenvalues of inertia_com_kg_m2, ascending.
  Eigen::Vector3d principal_moments_kg_m2 = Eigen::Vector3d::Zero();
  // Columns: unit principal axes in the mesh frame, matching principal_moments_kg_m2. A rotation
  // (right-handed); the largest component of the first two columns is positive. So
  // inertia_com = axes · diag(moments) · axesᵀ.
  Eigen::Matrix3d principal_axes = Eigen::Matrix3d::Identity();
};

// Signed enclosed volume, m³: positive when the faces wind counter-clockwise seen from outside.
double signed_volume_m3(const TriMesh& mesh);

// Mass properties of the solid the mesh bounds, at density_kg_m3 (> 0, finite: GEARSIM_CHECK,
// as is a positive volume; reject bad meshes with require_valid_solid first).
MassProperties mass_properties(const TriMesh& mesh, double density_kg_m3);

}  // namespace gearsim
