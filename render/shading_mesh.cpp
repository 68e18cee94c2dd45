#include "render/shading_mesh.hpp"
#include "geometry/constants.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace gearsim::render {
namespace {

using Eigen::Vector3d;
using gearsim::constants::kPi;

// Area-weighted (unnormalised) triangle normal.
Vector3d area_normal(const TriMesh& m, std::size_t t) {
  const auto& tri = m.triangles[t];
  const Vector3d& a = m.vertices[tri[0]];
  return (m.vertices[tri[1]] - a).cross(m.vertices[tri[2]] - a);
}

// Two unit vectors perpendicular to d and to each other.
void basis(const Vector3d& d, Vector3d& u, Vector3d& v) {
  u = (std::abs(d.x()) < 0.9 ? Vector3d::UnitX() : Vector3d::UnitY()).cross(d).normalized();
  v = d.cross(u);
}

std::uint32_t index(std::size_t i) { return static_cast<std::uint32_t>(i); }

}  // namespace

ShadingMesh shading_mesh(const TriMesh& m, double crease_angle_rad, const std::vector<std::uint8_t>* highlight) {
  const std::size_t nt = m.triangles.size();
  std::vector<Vector3d> weighted(nt), unit(nt);
  for (std::size_t t = 0; t < nt; ++t) {
    weighted[t] = area_normal(m, t);
    const double n = weighted[t].norm();
    unit[t] = n > 0 ? Vector3d(weighted[t] / n) : Vector3d::Zero();
  }
  // Triangles around each vertex (compressed adjacency).
  std::vector<std::uint32_t> start(m.vertices.size() + 1, 0), around(nt * 3);
  for (const auto& tri : m.triangles)
    for (std::uint32_t v : tri) ++start[v + 1];
  for (std::size_t v = 0; v < m.vertices.size(); ++v) start[v + 1] += start[v];
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (std::size_t t = 0; t < nt; ++t)
    for (std::uint32_t v : m.triangles[t]) around[fill[v]++] = index(t);

  const double cos_crease = std::cos(crease_angle_rad);
  const bool flat = crease_angle_rad <= 0;
  ShadingMesh out;
  out.indices.reserve(nt * 3);
  // Render vertices made so far for each mesh vertex (a handful at most).
  std::vector<std::vector<std::uint32_t>> made(m.vertices.size());
  for (std::size_t t = 0; t < nt; ++t) {
    const float h = highlight && !highlight->empty() && (*highlight)[t] ? 1.0f : 0.0f;
    for (std::uint32_t v : m.triangles[t]) {
      Vector3d n = unit[t];
      if (!flat || n.isZero()) {
        // Sum the neighbours within the crease angle (all of them for a degenerate triangle).
        Vector3d sum = Vector3d::Zero();
        for (std::uint32_t k = start[v]; k < start[v + 1]; ++k) {
          const std::uint32_t o = around[k];
          if (unit[t].isZero() || unit[t].dot(unit[o]) >= cos_crease) sum += weighted[o];
        }
        if (sum.norm() > 0) n = sum.normalized();
      }
      if (n.isZero()) n = Vector3d::UnitZ();
      const Vector3d& p = m.vertices[v];
      const ShadedVertex sv{{float(p.x()), float(p.y()), float(p.z())}, {float(n.x()), float(n.y()), float(n.z())}, h};
      const auto same = [&](std::uint32_t i) {
        const ShadedVertex& o = out.vertices[i];
        return o.normal[0] == sv.normal[0] && o.normal[1] == sv.normal[1] && o.normal[2] == sv.normal[2] && o.highlight == sv.highlight;
      };
      const auto it = std::find_if(made[v].begin(), made[v].end(), same);
      if (it != made[v].end()) {
        out.indices.push_back(*it);
      } else {
        made[v].push_back(index(out.vertices.size()));
        out.indices.push_back(index(out.vertices.size()));
        out.vertices.push_back(sv);
      }
    }
  }
  return out;
}

TriMesh sphere_mesh(const Vector3d& c, double r, int segments) {
  TriMesh m;
  const int rings = std::max(segments / 2, 2);
  m.vertices.push_back(c + Vector3d(0, 0, r));
  for (int i = 1; i < rings; ++i) {
    const double th = kPi * i / rings;
    for (int j = 0; j < segments; ++j) {
      const double ph = 2 * kPi * j / segments;
      m.vertices.push_back(c + r * Vector3d(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)));
    }
  }
  m.vertices.push_back(c - Vector3d(0, 0, r));
  const auto ring_v = [&](int i, int j) { return index(1 + (i - 1) * segments + (j % segments)); };
  const std::uint32_t bottom = index(m.vertices.size() - 1);
  for (int j = 0; j < segments; ++j) {
    m.triangles.push_back({0, ring_v(1, j), ring_v(1, j + 1)});
    for (int i = 1; i + 1 < rings; ++i) {
      m.triangles.push_back({ring_v(i, j), ring_v(i + 1, j), ring_v(i + 1, j + 1)});
      m.triangles.push_back({ring_v(i, j), ring_v(i + 1, j + 1), ring_v(i, j + 1)});
    }
    m.triangles.push_back({ring_v(rings - 1, j), bottom, ring_v(rings - 1, j + 1)});
  }
  return m;
}

TriMesh arrow_mesh(const Vector3d& from, const Vector3d& to, double shaft_r, int segments) {
  TriMesh m;
  const Vector3d axis = to - from;
  const double length = axis.norm();
  if (!(length > 0)) return m;
  const Vector3d d = axis / length;
  Vector3d u, v;
  basis(d, u, v);
  const double head_r = 2.5 * shaft_r, head_len = std::min(length / 3, 4 * head_r);
  const Vector3d neck = to - head_len * d;
  // Rings: shaft start, shaft end, head base; then the base cap's centre and the tip.
  const double radii[3] = {shaft_r, shaft_r, head_r};
  const Vector3d centres[3] = {from, neck, neck};
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < segments; ++j) {
      const double a = 2 * kPi * j / segments;
      m.vertices.push_back(centres[k] + radii[k] * (std::cos(a) * u + std::sin(a) * v));
    }
  const std::uint32_t c_from = index(m.vertices.size()), tip = c_from + 1;
  m.vertices.push_back(from);
  m.vertices.push_back(to);
  const auto rv = [&](int k, int j) { return index(k * segments + (j % segments)); };
  for (int j = 0; j < segments; ++j) {
    m.triangles.push_back({c_from, rv(0, j + 1), rv(0, j)});  // base cap
    m.triangles.push_back({rv(0, j), rv(0, j + 1), rv(1, j + 1)});  // shaft
    m.triangles.push_back({rv(0, j), rv(1, j + 1), rv(1, j)});
    m.triangles.push_back({rv(1, j), rv(2, j + 1), rv(2, j)});  // underside of the head
    m.triangles.push_back({rv(1, j), rv(1, j + 1), rv(2, j + 1)});
    m.triangles.push_back({rv(2, j), rv(2, j + 1), tip});  // cone
  }
  return m;
}

void append_mesh(TriMesh& a, const TriMesh& b) {
  const std::uint32_t offset = index(a.vertices.size());
  a.vertices.insert(a.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (const auto& t : b.triangles) a.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
}

}  // namespace gearsim::render
