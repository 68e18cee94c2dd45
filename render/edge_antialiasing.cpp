#include "render/edge_antialiasing.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "core/errors.hpp"
#include "render/constants.hpp"

namespace gearsim::render {
namespace {

using Eigen::Vector3d;
using Eigen::Vector4d;

// A point in clip space with its eye-space position (for the depth tolerance).
struct ClipPoint {
  Vector4d clip;
  Vector3d eye;
};

ClipPoint lerp(const ClipPoint& p, const ClipPoint& q, double t) { return {p.clip + t * (q.clip - p.clip), p.eye + t * (q.eye - p.eye)}; }

// Clips the segment pq to the side of a clip-space plane where d(·) ≥ 0; false when nothing is left.
template <class Distance>
bool clip_to(ClipPoint& p, ClipPoint& q, Distance d) {
  const double dp = d(p.clip), dq = d(q.clip);
  if (dp < 0 && dq < 0) return false;
  if (dp < 0) p = lerp(p, q, dp / (dp - dq));
  if (dq < 0) q = lerp(q, p, dq / (dq - dp));
  return true;
}

// Window depth of clip-space point c.
double window_z(const Vector4d& c, const EdgeProjection& v) {
  return v.depth_near + (v.depth_far - v.depth_near) * 0.5 * (c.z() / c.w() + 1.0);
}

// Window position, depth and depth tolerance of a clipped end point.
void to_window(const ClipPoint& p, const EdgeProjection& v, float& x, float& y, float& z, float& tol) {
  x = static_cast<float>(0.5 * (p.clip.x() / p.clip.w() + 1.0) * v.width_px);
  y = static_cast<float>(0.5 * (p.clip.y() / p.clip.w() + 1.0) * v.height_px);
  const double zw = window_z(p.clip, v);
  z = static_cast<float>(zw);
  // Pixel footprint at this depth, m: 2 / (|P₁₁| · height) per metre of eye distance in
  // perspective (w is the eye distance), constant in orthographic (w = 1).
  const double pixel_m = 2.0 * p.clip.w() / (std::abs(v.projection(1, 1)) * v.height_px);
  const Vector3d nearer = p.eye + Vector3d(0, 0, constants::kEdgeDepthTolerance_px * pixel_m);
  const Vector4d c = v.projection * nearer.homogeneous();
  tol = static_cast<float>(c.w() > 0 ? zw - window_z(c, v) : zw);
}

// Clips the window segment e to the frame grown by a pixel on every side (Liang–Barsky); false
// when nothing is left. Off-frame stretches would only cost time: no pixel of theirs exists.
bool clip_to_frame(WindowEdge& e, int width, int height) {
  const double dx = e.x1 - e.x0, dy = e.y1 - e.y0;
  double t0 = 0, t1 = 1;
  const auto clip = [&](double p, double q) {  // keep where p·t ≤ q
    if (p == 0) return q >= 0;
    const double t = q / p;
    if (p < 0)
      t0 = std::max(t0, t);
    else
      t1 = std::min(t1, t);
    return t0 <= t1;
  };
  const double x0 = e.x0, y0 = e.y0;
  if (!clip(-dx, x0 + 1) || !clip(dx, width + 1 - x0) || !clip(-dy, y0 + 1) || !clip(dy, height + 1 - y0)) return false;
  const WindowEdge o = e;
  const auto at = [](float a, float b, double t) { return static_cast<float>(a + t * (b - a)); };
  e = {at(o.x0, o.x1, t0), at(o.y0, o.y1, t0), at(o.z0, o.z1, t0), at(o.tol0, o.tol1, t0),
       at(o.x0, o.x1, t1), at(o.y0, o.y1, t1), at(o.z0, o.z1, t1), at(o.tol0, o.tol1, t1)};
  return true;
}

// ∫_{-½}^{½} clamp(g + k·t, 0, 1) dt: the fraction of a pixel row's square below a line that
// crosses the pixel's centre column at height g above the row's bottom with slope k (|k| ≤ 1).
double area_below(double g, double k) {
  if (std::abs(k) < 1e-9) return std::clamp(g, 0.0, 1.0);
  const auto h = [](double u) { return u <= 0 ? 0.0 : u <= 1 ? 0.5 * u * u : u - 0.5; };  // ∫₀ᵘ clamp(s, 0, 1) ds
  return (h(g + 0.5 * k) - h(g - 0.5 * k)) / k;
}

}  // namespace

MeshEdges mesh_edges(const TriMesh& m, double crease_angle_rad, const std::vector<std::uint8_t>* highlight) {
  const std::size_t nt = m.triangles.size();
  std::vector<Vector3d> normal(nt);
  for (std::size_t t = 0; t < nt; ++t) {
    const auto& tri = m.triangles[t];
    const Vector3d n = (m.vertices[tri[1]] - m.vertices[tri[0]]).cross(m.vertices[tri[2]] - m.vertices[tri[0]]);
    normal[t] = n.norm() > 0 ? Vector3d(n.normalized()) : Vector3d::Zero();
  }
  // Every triangle side as (lower vertex, higher vertex, triangle), sorted: the sides of one edge meet.
  std::vector<std::array<std::uint32_t, 3>> sides;
  sides.reserve(3 * nt);
  for (std::size_t t = 0; t < nt; ++t)
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = m.triangles[t][i], b = m.triangles[t][(i + 1) % 3];
      sides.push_back({std::min(a, b), std::max(a, b), static_cast<std::uint32_t>(t)});
    }
  std::sort(sides.begin(), sides.end());
  const double cos_crease = std::cos(crease_angle_rad);
  const auto lit = [&](std::uint32_t t) { return highlight && !highlight->empty() && (*highlight)[t] != 0; };
  MeshEdges out;
  for (std::size_t i = 0; i < sides.size();) {
    std::size_t j = i + 1;
    while (j < sides.size() && sides[j][0] == sides[i][0] && sides[j][1] == sides[i][1]) ++j;
    const std::uint32_t t0 = sides[i][2], t1 = sides[j - 1][2];
    const std::size_t faces = j - i;
    i = j;
    const Vector3d& n0 = normal[t0];
    const Vector3d& n1 = normal[t1];
    if (n0.isZero() || n1.isZero()) continue;
    const double cos_angle = n0.dot(n1);
    const bool feature = faces != 2 || cos_angle < cos_crease || lit(t0) != lit(t1);
    if (!feature && cos_angle > 1.0 - constants::kCoplanarCosineTolerance) continue;  // never a silhouette
    const auto f = [](const Vector3d& v) { return v.cast<float>().eval(); };
    out.edges.push_back({f(m.vertices[sides[j - 1][0]]), f(m.vertices[sides[j - 1][1]]), f(n0), f(n1), feature});
  }
  return out;
}

void append_outline_edges(const MeshEdges& edges, const Eigen::Matrix4d& model_view, const EdgeProjection& v,
                          std::vector<WindowEdge>& out) {
  // The eye in the body frame (perspective: w = 1) or the direction toward it (orthographic: w = 0).
  const bool perspective = v.projection(3, 3) == 0;
  const Eigen::Matrix4d body_from_eye = model_view.inverse();
  const Eigen::Vector3f eye = body_from_eye.col(3).head<3>().cast<float>();
  const Eigen::Vector3f toward_eye = body_from_eye.col(2).head<3>().cast<float>();
  for (const MeshEdges::Edge& e : edges.edges) {
    const Eigen::Vector3f to_eye = perspective ? Eigen::Vector3f(eye - e.a) : toward_eye;
    const bool front0 = e.n0.dot(to_eye) > 0, front1 = e.n1.dot(to_eye) > 0;
    const bool outline = front0 != front1 || (e.feature && front0 && front1);
    if (!outline) continue;
    ClipPoint p, q;
    p.eye = (model_view * e.a.cast<double>().homogeneous()).head<3>();
    q.eye = (model_view * e.b.cast<double>().homogeneous()).head<3>();
    p.clip = v.projection * p.eye.homogeneous();
    q.clip = v.projection * q.eye.homogeneous();
    if (!clip_to(p, q, [](const Vector4d& c) { return c.z() + c.w(); })) continue;  // near plane
    if (!clip_to(p, q, [](const Vector4d& c) { return c.w() - c.z(); })) continue;  // far plane
    WindowEdge w;
    to_window(p, v, w.x0, w.y0, w.z0, w.tol0);
    to_window(q, v, w.x1, w.y1, w.z1, w.tol1);
    out.push_back(w);
  }
}

void antialias_edges(Image& image, const std::vector<float>& depth, const std::vector<WindowEdge>& edges, EdgeBlendBuffers& buffers) {
  const int width = image.width_px, height = image.height_px;
  const std::size_t pixels = std::size_t(width) * height;
  GEARSIM_CHECK(depth.size() == pixels, "edge anti-aliasing: the depth buffer's size differs from the image's");
  buffers.sums.resize(pixels);
  buffers.touched.clear();
  for (WindowEdge e : edges) {
    if (!clip_to_frame(e, width, height)) continue;
    // Walk along the major axis u (x or y); v is the other. Pixel (u, v) ↔ image (x, y).
    const bool x_major = std::abs(e.x1 - e.x0) >= std::abs(e.y1 - e.y0);
    double u0 = x_major ? e.x0 : e.y0, v0 = x_major ? e.y0 : e.x0, z0 = e.z0, tol0 = e.tol0;
    double u1 = x_major ? e.x1 : e.y1, v1 = x_major ? e.y1 : e.x1, z1 = e.z1, tol1 = e.tol1;
    if (u1 < u0) {
      std::swap(u0, u1), std::swap(v0, v1), std::swap(z0, z1), std::swap(tol0, tol1);
    }
    if (!(u1 > u0)) continue;
    const int u_size = x_major ? width : height, v_size = x_major ? height : width;
    const double k = (v1 - v0) / (u1 - u0);
    // Columns whose centre lies in [u0, u1): neighbouring edges of a polyline share none.
    const int c_begin = std::max(0, static_cast<int>(std::ceil(u0 - 0.5)));
    const int c_end = std::min(u_size, static_cast<int>(std::ceil(u1 - 0.5)));
    for (int c = c_begin; c < c_end; ++c) {
      const double t = (c + 0.5 - u0) / (u1 - u0);
      const double vc = v0 + t * (v1 - v0);  // the edge at the column's centre
      const double z = z0 + t * (z1 - z0), tol = tol0 + t * (tol1 - tol0);
      const int first_beyond = static_cast<int>(std::ceil(vc - 0.5));  // first row whose centre is ≥ vc
      const int r_lo = static_cast<int>(std::floor(vc - 0.5 * std::abs(k)));
      const int r_hi = static_cast<int>(std::floor(vc + 0.5 * std::abs(k)));
      for (int r = std::max(r_lo, 0); r <= std::min(r_hi, v_size - 1); ++r) {
        const double below = area_below(vc - r, k);  // the part of pixel r on the low-v side
        const bool own_low = r < first_beyond;
        const double w = own_low ? 1.0 - below : below;  // the part across the edge
        const int across = own_low ? first_beyond : first_beyond - 1;
        if (!(w > 0) || across < 0 || across >= v_size) continue;
        const int x = x_major ? c : r, y = x_major ? r : c;
        const int xa = x_major ? c : across, ya = x_major ? across : c;
        const std::size_t p = std::size_t(y) * width + x, a = std::size_t(ya) * width + xa;
        if (std::max(depth[p], depth[a]) < z - tol) continue;  // something in front hides the edge here
        EdgeBlendBuffers::Sum& sum = buffers.sums[p];
        if (sum.weight == 0) buffers.touched.push_back(static_cast<std::uint32_t>(p));
        const float wf = static_cast<float>(w);
        sum.weight += wf;
        sum.r += wf * image.rgb[3 * a];
        sum.g += wf * image.rgb[3 * a + 1];
        sum.b += wf * image.rgb[3 * a + 2];
      }
    }
  }
  // Every blend read the frame as drawn; apply them all now (each pixel reads only itself), and
  // clear the sums for the next frame.
  for (const std::uint32_t p : buffers.touched) {
    EdgeBlendBuffers::Sum& sum = buffers.sums[p];
    const float across = std::min(sum.weight, 1.0f), scale = across / sum.weight;
    const float mixed[3] = {sum.r, sum.g, sum.b};
    for (int ch = 0; ch < 3; ++ch) {
      const float v = (1.0f - across) * image.rgb[3 * p + ch] + scale * mixed[ch];
      image.rgb[3 * p + ch] = static_cast<std::uint8_t>(std::clamp(std::lround(v), 0L, 255L));
    }
    sum = {};
  }
}

}  // namespace gearsim::render
