// Analytic edge anti-aliasing of a frame drawn with one sample per pixel. The renderer knows the
// geometry, so instead of guessing edges from colours (FXAA) or paying for several samples per
// pixel (MSAA 4×: ~35 ms more CPU per 1280×720 frame on llvmpipe, bench_render), it finds the edges that
// outline what was drawn — silhouettes (one face toward the eye, one away), creases sharper than
// the crease angle and highlight boundaries with both faces toward the eye, open boundaries — and
// gives every pixel such an edge crosses the exact fraction of its area that lies across the edge,
// taken from the nearest pixel on that side (a straight line through a square, closed form; the
// idea of Persson's "geometric post-process anti-aliasing", computed on the CPU after read-back).
// Hidden edges are skipped by a depth test against the read-back depth buffer.
// Not a general image filter: texture or shading detail inside faces stays as drawn.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "geometry/mesh.hpp"
#include "render/image.hpp"

namespace gearsim::render {

// The edges of a mesh that can outline it, body frame (m), found once per mesh: every edge between
// two faces (it becomes a silhouette when they face opposite ways) except those between faces of
// one plane, which never can; `feature` marks creases sharper than the crease angle, highlight
// boundaries and open boundaries, which outline whenever their faces face the eye. Edges of a
// degenerate (zero-area) face are left out: it faces no way.
struct MeshEdges {
  struct Edge {
    Eigen::Vector3f a, b;  // end points, m
    Eigen::Vector3f n0, n1;  // unit normals of the two faces (equal for an open boundary)
    bool feature = false;
  };
  std::vector<Edge> edges;
};

MeshEdges mesh_edges(const TriMesh& mesh, double crease_angle_rad, const std::vector<std::uint8_t>* highlight = nullptr);

// An edge in window coordinates: x right and y down in pixels (pixel (i, j) covers
// [i, i+1] × [j, j+1]), z the depth-buffer value; tol is how far (in depth-buffer units) the
// surface beside the edge may lie in front of it and the edge still count as visible.
struct WindowEdge {
  float x0, y0, z0, tol0;
  float x1, y1, z1, tol1;
};

// How edges are projected: eye → clip as drawn (y already flipped so that window rows are image
// rows), the viewport and the depth range the body was drawn with (glDepthRange).
struct EdgeProjection {
  Eigen::Matrix4d projection = Eigen::Matrix4d::Identity();
  int width_px = 0, height_px = 0;
  double depth_near = 0, depth_far = 1;
};

// Appends the edges of `edges` (posed by model_view: body → eye) that outline the body in this
// view, clipped to the near and far planes, in window coordinates.
void append_outline_edges(const MeshEdges& edges, const Eigen::Matrix4d& model_view, const EdgeProjection& view,
                          std::vector<WindowEdge>& out);

// Per-pixel sums antialias_edges() keeps between frames so as not to allocate: all zero between calls.
struct EdgeBlendBuffers {
  struct Sum {
    float weight = 0;  // the summed fractions across edges
    float r = 0, g = 0, b = 0;  // the summed fraction × colour across
  };
  std::vector<Sum> sums;  // per pixel (one cache line holds a pixel's four)
  std::vector<std::uint32_t> touched;  // pixels with a non-zero weight
};

// Blends each pixel a visible edge crosses with the pixel across the edge by the fraction of its
// area beyond the edge, reading colours from the frame as drawn. Where several edges cross one
// pixel (tooth tips, corners) and their fractions add up to more than 1, they are scaled to 1: the
// result stays a mix of colours drawn nearby. depth: the depth buffer, one value per pixel in
// [0, 1], rows as the image's. An edge is visible at a pixel when the deeper of the pixel and its
// neighbour across lies no nearer than the edge's depth minus its tolerance.
void antialias_edges(Image& image, const std::vector<float>& depth, const std::vector<WindowEdge>& edges, EdgeBlendBuffers& buffers);

}  // namespace gearsim::render
