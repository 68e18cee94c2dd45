// Internal to render/: the one GLSL 330 core program every frame uses — Blinn–Phong with a key
// and a fill light fixed to the camera, lit in linear light (gamma 2 standing in for sRGB) — or
// the exact base colour unlit (for coverage measurements). A compile or link failure is a bug: InternalError with the
// driver's log.
#pragma once

#include "render/gl.hpp"

namespace gearsim::render {

class ShadingProgram {
 public:
  ShadingProgram();
  ~ShadingProgram();
  ShadingProgram(const ShadingProgram&) = delete;
  ShadingProgram& operator=(const ShadingProgram&) = delete;

  GLuint id() const { return program_; }
  // Uniform locations.
  GLint model_view = -1, projection = -1, normal_matrix = -1, colour = -1, highlight_colour = -1, lit = -1, orthographic = -1;

 private:
  GLuint program_ = 0;
};

// Vertex attribute locations (match ShadedVertex in shading_mesh.hpp).
inline constexpr GLuint kPositionAttribute = 0, kNormalAttribute = 1, kHighlightAttribute = 2;

}  // namespace gearsim::render
