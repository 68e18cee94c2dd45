#include "geometry/mesh_validate.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <numeric>
#include <tuple>
#include <vector>

#include "core/errors.hpp"
#include "geometry/mass_properties.hpp"

namespace gearsim {
namespace {

using Triangle = std::array<std::uint32_t, 3>;

bool repeats_vertex(const Triangle& t) { return t[0] == t[1] || t[1] == t[2] || t[0] == t[2]; }

// One face's side of an edge {lo, hi}; slot_* are the corners (0..2) of lo and hi in the face.
struct HalfEdge {
  std::uint32_t lo, hi, face;
  std::uint8_t slot_lo, slot_hi;
  bool forward() const { return slot_hi == (slot_lo + 1) % 3; }  // the face runs lo -> hi
};

// Union-find over face corners (3 per face): corners of one vertex joined across shared edges
// form the fans around that vertex. The smaller index becomes the root, so results are stable.
class CornerSets {
 public:
  explicit CornerSets(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
  std::size_t find(std::size_t c) {
    while (parent_[c] != c) c = parent_[c] = parent_[parent_[c]];
    return c;
  }
  void unite(std::size_t a, std::size_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<std::size_t> parent_;
};

std::size_t corner(std::uint32_t face, std::uint8_t slot) { return 3 * std::size_t{face} + slot; }

// The edge half[g, e) as a defect, in the winding of its lowest face.
EdgeDefect edge_defect(const TriMesh& mesh, const std::vector<HalfEdge>& half, std::size_t g, std::size_t e) {
  const HalfEdge& h = half[g];
  EdgeDefect d;
  d.vertices = h.forward() ? std::array{h.lo, h.hi} : std::array{h.hi, h.lo};
  d.p_m = {mesh.vertices[d.vertices[0]], mesh.vertices[d.vertices[1]]};
  d.face = h.face;
  d.other_face = e - g > 1 ? half[g + 1].face : kNoIndex;
  d.face_count = static_cast<std::uint32_t>(e - g);
  return d;
}

// Keeps the defect on the lowest face (the first one met on a tie).
void keep_first(std::optional<EdgeDefect>& first, const EdgeDefect& d) {
  if (!first || d.face < first->face) first = d;
}

// Fills the finite and degenerate-face checks.
void check_faces(const TriMesh& mesh, const std::vector<std::uint32_t>& first_face, MeshReport& r) {
  for (std::uint32_t v = 0; v < mesh.vertices.size(); ++v) {
    if (mesh.vertices[v].allFinite()) continue;
    if (r.nonfinite_vertex_count++ == 0) {
      r.first_nonfinite_vertex = VertexDefect{v, mesh.vertices[v], first_face[v], 0};
    }
  }
  for (std::uint32_t f = 0; f < mesh.triangles.size(); ++f) {
    const Triangle& t = mesh.triangles[f];
    const Eigen::Vector3d &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    const double longest2 = std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
    const double twice_area = (b - a).cross(c - a).norm();
    // NaN compares false: a non-finite face is reported as such, not as degenerate.
    const bool thin = twice_area <= constants::kDegenerateFaceRelativeHeight * longest2;  // h/L = 2A/L²
    if (!repeats_vertex(t) && !thin) continue;
    if (r.degenerate_face_count++ == 0) r.first_degenerate_face = FaceDefect{f, t, {a, b, c}, 0.5 * twice_area};
  }
}

// Fills the edge checks (open, non-manifold, misoriented) and the non-manifold-vertex check.
void check_topology(const TriMesh& mesh, const std::vector<std::uint32_t>& first_face, MeshReport& r) {
  std::vector<HalfEdge> half;
  half.reserve(3 * mesh.triangles.size());
  for (std::uint32_t f = 0; f < mesh.triangles.size(); ++f) {
    const Triangle& t = mesh.triangles[f];
    if (repeats_vertex(t)) continue;
    for (std::uint8_t s = 0; s < 3; ++s) {
      const auto s2 = static_cast<std::uint8_t>((s + 1) % 3);
      if (t[s] < t[s2])
        half.push_back({t[s], t[s2], f, s, s2});
      else
        half.push_back({t[s2], t[s], f, s2, s});
    }
  }
  std::sort(half.begin(), half.end(),
            [](const HalfEdge& x, const HalfEdge& y) { return std::tie(x.lo, x.hi, x.face) < std::tie(y.lo, y.hi, y.face); });

  CornerSets fans(3 * mesh.triangles.size());
  for (std::size_t g = 0, e = 0; g < half.size(); g = e) {
    e = g + 1;
    while (e < half.size() && half[e].lo == half[g].lo && half[e].hi == half[g].hi) ++e;
    // Faces sharing the edge belong to the same fan at both of its ends.
    for (std::size_t k = g + 1; k < e; ++k) {
      fans.unite(corner(half[k - 1].face, half[k - 1].slot_lo), corner(half[k].face, half[k].slot_lo));
      fans.unite(corner(half[k - 1].face, half[k - 1].slot_hi), corner(half[k].face, half[k].slot_hi));
    }
    if (e - g == 1) {
      ++r.open_edge_count;
      keep_first(r.first_open_edge, edge_defect(mesh, half, g, e));
    } else if (e - g > 2) {
      ++r.nonmanifold_edge_count;
      keep_first(r.first_nonmanifold_edge, edge_defect(mesh, half, g, e));
    } else if (half[g].forward() == half[g + 1].forward()) {
      ++r.misoriented_edge_count;
      keep_first(r.first_misoriented_edge, edge_defect(mesh, half, g, e));
    }
  }

  // A vertex is manifold when all its corners fall in one set (one fan, open or closed).
  std::vector<std::uint32_t> fan_count(mesh.vertices.size(), 0);
  for (std::uint32_t f = 0; f < mesh.triangles.size(); ++f) {
    if (repeats_vertex(mesh.triangles[f])) continue;
    for (std::uint8_t s = 0; s < 3; ++s) {
      if (fans.find(corner(f, s)) == corner(f, s)) ++fan_count[mesh.triangles[f][s]];
    }
  }
  for (std::uint32_t v = 0; v < mesh.vertices.size(); ++v) {
    if (fan_count[v] <= 1) continue;
    if (r.nonmanifold_vertex_count++ == 0) {
      r.first_nonmanifold_vertex = VertexDefect{v, mesh.vertices[v], first_face[v], fan_count[v]};
    }
  }
}

// --- Messages ---------------------------------------------------------------------------------

// Six significant digits, locale-independent.
std::string num(double v) {
  char buf[32];
  const auto result = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 6);
  return std::string(buf, result.ptr);
}

std::string mm(const Eigen::Vector3d& p_m) {
  return "(" + num(1e3 * p_m.x()) + ", " + num(1e3 * p_m.y()) + ", " + num(1e3 * p_m.z()) + ") mm";
}

std::string edge_text(const EdgeDefect& d) {
  return "edge (" + std::to_string(d.vertices[0]) + ", " + std::to_string(d.vertices[1]) + ") from " + mm(d.p_m[0]) + " to " + mm(d.p_m[1]);
}

// "1 face", "3 faces".
std::string count(std::size_t n, const char* one, const char* many) { return std::to_string(n) + " " + (n == 1 ? one : many); }

std::string vertex_list(const std::array<std::uint32_t, 3>& v) {
  return std::to_string(v[0]) + ", " + std::to_string(v[1]) + ", " + std::to_string(v[2]);
}

}  // namespace

MeshReport validate_mesh(const TriMesh& mesh) {
  MeshReport r;
  r.triangle_count = mesh.triangles.size();
  r.vertex_count = mesh.vertices.size();
  GEARSIM_CHECK(mesh.triangles.size() < kNoIndex && mesh.vertices.size() < kNoIndex, "mesh too large for 32-bit indices");
  // Lowest face using each vertex; also checks the index invariant.
  std::vector<std::uint32_t> first_face(mesh.vertices.size(), kNoIndex);
  for (std::uint32_t f = 0; f < mesh.triangles.size(); ++f) {
    for (std::uint32_t v : mesh.triangles[f]) {
      GEARSIM_CHECK(v < mesh.vertices.size(), "triangle " + std::to_string(f) + " references vertex " + std::to_string(v) + " of " +
                                                  std::to_string(mesh.vertices.size()));
      first_face[v] = std::min(first_face[v], f);
    }
  }
  check_faces(mesh, first_face, r);
  check_topology(mesh, first_face, r);
  r.signed_volume_m3 = signed_volume_m3(mesh);
  return r;
}

void require_valid_solid(const MeshReport& r, const std::string& source_name) {
  const std::string at = source_name + ": ";
  if (r.triangle_count == 0) throw InputError(at + "no triangles; expected a closed surface");
  if (const auto& d = r.first_nonfinite_vertex) {
    throw InputError(at + "vertex " + std::to_string(d->vertex) + " has a non-finite coordinate " + mm(d->p_m) + " (face " +
                     std::to_string(d->face) + "; " + count(r.nonfinite_vertex_count, "such vertex", "such vertices") +
                     "); expected finite coordinates");
  }
  if (const auto& d = r.first_degenerate_face) {
    const bool repeated = repeats_vertex(d->vertices);
    throw InputError(at + "degenerate face " + std::to_string(d->face) + " (vertices " + vertex_list(d->vertices) + ") at " +
                     mm(d->p_m[0]) +
                     (repeated ? " repeats a vertex"
                               : " has area " + num(d->area_m2) + " m^2, height under " + num(constants::kDegenerateFaceRelativeHeight) +
                                     " of its longest edge") +
                     " (" + count(r.degenerate_face_count, "such face", "such faces") + "); expected proper triangles");
  }
  if (const auto& d = r.first_nonmanifold_edge) {
    throw InputError(at + "not manifold: " + edge_text(*d) + " belongs to " + std::to_string(d->face_count) + " faces (faces " +
                     std::to_string(d->face) + ", " + std::to_string(d->other_face) + ", ...); expected at most two");
  }
  if (const auto& d = r.first_nonmanifold_vertex) {
    throw InputError(at + "not manifold: vertex " + std::to_string(d->vertex) + " at " + mm(d->p_m) + " joins " +
                     std::to_string(d->fan_count) + " separate fans of faces (first face " + std::to_string(d->face) +
                     "); expected one fan, not surfaces touching at a point");
  }
  if (const auto& d = r.first_open_edge) {
    throw InputError(at + "not watertight: " + edge_text(*d) + " belongs to 1 face (face " + std::to_string(d->face) + "; " +
                     count(r.open_edge_count, "open edge", "open edges") + "); expected every edge shared by exactly two faces");
  }
  if (const auto& d = r.first_misoriented_edge) {
    throw InputError(at + "inconsistent orientation: " + edge_text(*d) + " is traversed in the same direction by faces " +
                     std::to_string(d->face) + " and " + std::to_string(d->other_face) +
                     " (one of them is flipped); expected opposite directions");
  }
  if (!r.outward_oriented()) {
    throw InputError(at + "inside out: signed volume " + num(r.signed_volume_m3) +
                     " m^3 is not positive; expected faces counter-clockwise seen from outside");
  }
}

}  // namespace gearsim
