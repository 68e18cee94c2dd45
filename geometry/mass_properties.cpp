#include "geometry/mass_properties.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <cmath>

#include "core/errors.hpp"

namespace gearsim {
namespace {

// Mean of the vertices: the apex every face's tetrahedron shares. Near the centroid, it keeps
// the accumulated moments of the order of the part's own size, so their rounding stays relative
// to it however far the part sits from the origin.
Eigen::Vector3d reference_point(const TriMesh& mesh) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : mesh.vertices) sum += p;
  return mesh.vertices.empty() ? sum : Eigen::Vector3d(sum / double(mesh.vertices.size()));
}

// Volume integrals of the solid, positions measured from a reference point o:
// ∫dV (m³), ∫r dV (m⁴), ∫r rᵀ dV (m⁵).
struct VolumeMoments {
  double volume = 0.0;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
};

// Sums the tetrahedra (o, a, b, c), one per face. For a tetrahedron with one vertex at the origin
// and volume V = a·(b×c)/6 (signed):  ∫r dV = V (a+b+c)/4  and
// ∫r rᵀ dV = V/20 (a aᵀ + b bᵀ + c cᵀ + s sᵀ), s = a+b+c  (exact; cf. Tonon 2004).
VolumeMoments volume_moments(const TriMesh& mesh, const Eigen::Vector3d& o, bool second) {
  VolumeMoments m;
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d a = mesh.vertices[t[0]] - o;
    const Eigen::Vector3d b = mesh.vertices[t[1]] - o;
    const Eigen::Vector3d c = mesh.vertices[t[2]] - o;
    const double v = a.dot(b.cross(c)) / 6.0;
    const Eigen::Vector3d s = a + b + c;
    m.volume += v;
    if (!second) continue;
    m.first += (v / 4.0) * s;
    m.second += (v / 20.0) * (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
  }
  return m;
}

}  // namespace

double signed_volume_m3(const TriMesh& mesh) { return volume_moments(mesh, reference_point(mesh), false).volume; }

MassProperties mass_properties(const TriMesh& mesh, double density_kg_m3) {
  GEARSIM_CHECK(std::isfinite(density_kg_m3) && density_kg_m3 > 0.0,
                "density must be positive and finite, got " + std::to_string(density_kg_m3));
  const Eigen::Vector3d o = reference_point(mesh);
  const VolumeMoments m = volume_moments(mesh, o, true);
  GEARSIM_CHECK(m.volume > 0.0, "mesh encloses no positive volume (" + std::to_string(m.volume) + " m^3): validate it first");

  MassProperties p;
  p.volume_m3 = m.volume;
  p.mass_kg = density_kg_m3 * m.volume;
  // Centre of mass from o, then the second moment moved from o to it (parallel axis).
  const Eigen::Vector3d r = m.first / m.volume;
  p.centre_of_mass_m = o + r;
  const Eigen::Matrix3d second_com = m.second - m.volume * r * r.transpose();
  p.inertia_com_kg_m2 = density_kg_m3 * (second_com.trace() * Eigen::Matrix3d::Identity() - second_com);

  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(p.inertia_com_kg_m2);
  GEARSIM_CHECK(eigen.info() == Eigen::Success, "inertia eigen-decomposition failed");
  p.principal_moments_kg_m2 = eigen.eigenvalues();
  p.principal_axes = eigen.eigenvectors();
  // Fix the signs (eigenvectors are defined up to sign): deterministic and right-handed.
  for (int k = 0; k < 2; ++k) {
    Eigen::Index largest = 0;
    p.principal_axes.col(k).cwiseAbs().maxCoeff(&largest);
    if (p.principal_axes(largest, k) < 0.0) p.principal_axes.col(k) *= -1.0;
  }
  p.principal_axes.col(2) = p.principal_axes.col(0).cross(p.principal_axes.col(1));
  return p;
}

}  // namespace gearsim
