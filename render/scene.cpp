#include "render/scene.hpp"

#include <cmath>
#include <limits>

#include "core/errors.hpp"

namespace gearsim::render {
namespace {

void validate_body(const SceneBody& b, std::size_t index) {
  const std::string who = "scene: body " + std::to_string(index) + (b.name.empty() ? "" : " '" + b.name + "'");
  if (!b.mesh || b.mesh->triangles.empty()) throw InputError(who + ": has no mesh (no triangles)");
  const std::size_t nv = b.mesh->vertices.size();
  for (const auto& t : b.mesh->triangles)
    for (std::uint32_t i : t)
      if (i >= nv) throw InputError(who + ": triangle index " + std::to_string(i) + " ≥ vertex count " + std::to_string(nv));
  for (const Eigen::Vector3d& v : b.mesh->vertices)
    if (!v.allFinite()) throw InputError(who + ": non-finite vertex");
  if (b.highlight && !b.highlight->empty() && b.highlight->size() != b.mesh->triangles.size())
    throw InputError(who + ": highlight has " + std::to_string(b.highlight->size()) + " entries, expected one per triangle (" +
                     std::to_string(b.mesh->triangles.size()) + ")");
  const Eigen::Matrix4d& m = b.pose.matrix();
  if (!m.allFinite()) throw InputError(who + ": pose is not finite (no pose given?)");
  const Eigen::Matrix3d r = b.pose.linear();
  const double off = (r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (off > constants::kPoseRigidityTolerance || r.determinant() < 0 || m.row(3) != Eigen::RowVector4d(0, 0, 0, 1))
    throw InputError(who + ": pose is not a rigid transform (rotation + translation)");
}

}  // namespace

void validate_scene(const Scene& s) {
  if (s.bodies.empty()) throw InputError("scene: no bodies to draw");
  for (std::size_t i = 0; i < s.bodies.size(); ++i) validate_body(s.bodies[i], i);
  for (std::size_t i = 0; i < s.contacts.size(); ++i)
    if (!s.contacts[i].point_m.allFinite() || !s.contacts[i].force_N.allFinite())
      throw InputError("scene: contact " + std::to_string(i) + ": point_m and force_N must be finite");
  if (!(s.arrow_m_per_N >= 0) || !std::isfinite(s.arrow_m_per_N)) throw InputError("scene: arrow_m_per_N must be finite and ≥ 0");
  if (!(s.marker_radius_m > 0) || !std::isfinite(s.marker_radius_m)) throw InputError("scene: marker_radius_m must be positive");
}

Bounds scene_bounds(const Scene& s) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  Bounds b{Eigen::Vector3d::Constant(inf), Eigen::Vector3d::Constant(-inf)};
  for (const SceneBody& body : s.bodies) {
    if (!body.mesh) continue;
    for (const Eigen::Vector3d& v : body.mesh->vertices) {
      const Eigen::Vector3d p = body.pose * v;
      b.min_m = b.min_m.cwiseMin(p);
      b.max_m = b.max_m.cwiseMax(p);
    }
  }
  if (!b.min_m.allFinite()) throw InputError("scene: no bodies with vertices to bound");
  return b;
}

}  // namespace gearsim::render
