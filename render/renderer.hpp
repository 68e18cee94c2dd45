// Renderer: draws a Scene through a Camera into an Image, offscreen (OSMesa, OpenGL 3.3 core),
// with Blinn–Phong shading (key + fill light), crease-angle normals and edge anti-aliasing (or
// MSAA, or supersampling).
// Contact markers and force arrows are drawn over the bodies; overlay text last. Meshes are
// uploaded once per (mesh, highlight) pointer pair and kept while anyone else still holds them.
// Not a window or an animation loop; one Renderer per thread (its GL context is thread-bound).
#pragma once

#include <memory>
#include <string>

#include "render/camera.hpp"
#include "render/constants.hpp"
#include "render/image.hpp"
#include "render/scene.hpp"

namespace gearsim::render {

enum class Lighting {
  BlinnPhong,  // shaded
  None,  // each body in its exact base colour (coverage and silhouette measurements)
};

// How a frame is anti-aliased. CPU per 1280×720 frame of the paper's set on llvmpipe, 2 cores
// (bench_render, overview / close-up): none 18 / 23 ms; edge 22 / 26 ms (depth read-back, ~13 000
// outline edges, ~22 000 blended pixels); multisampling 4× 52 / 65 ms (four samples drawn and
// cleared, a ~10 ms resolve blit); supersampling 2×2 48 / 75 ms.
enum class AntiAliasing {
  None,  // one sample per pixel: its centre decides (coverage measurements)
  Edge,  // one sample per pixel, then analytic edge anti-aliasing (edge_antialiasing.hpp)
  Multisample,  // msaa_samples samples per pixel, resolved by GL
  Supersample,  // drawn at twice the width and height and box-filtered down (2×2 samples)
};

struct RenderSettings {
  int width_px = 1280;
  int height_px = 720;
  AntiAliasing anti_aliasing = AntiAliasing::Edge;
  int msaa_samples = constants::kDefaultMsaaSamples;  // used with AntiAliasing::Multisample
  Rgb background{28, 31, 38};
  Lighting lighting = Lighting::BlinnPhong;
  double crease_angle_rad = constants::kDefaultCreaseAngle_rad;  // 0: flat (face) normals
  int text_scale = 2;  // overlay font magnification
  // Skip triangles facing away from the camera: right for closed, outward-oriented meshes (every
  // TriMesh of the geometry pipeline), about half the rasterisation work. Off for open meshes.
  bool cull_back_faces = true;
};

// Throws InputError naming the field: width/height outside [1, kMaxImageSize_px] (after
// supersampling), fewer than 2 MSAA samples with multisampling, a crease angle outside [0, π], a
// text scale < 1.
void validate_render_settings(const RenderSettings& settings);

class Renderer {
 public:
  // Validates the settings, then creates the GL context (RenderError when OSMesa cannot give a
  // 3.3 core context; InputError when the size or samples exceed what it supports).
  explicit Renderer(const RenderSettings& settings = {});
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Throws InputError for an invalid scene or camera (validate_scene, validate_camera).
  Image render(const Scene& scene, const Camera& camera);

  const RenderSettings& settings() const;
  double aspect() const;  // width / height
  std::string gl_description() const;  // GL_VERSION on GL_RENDERER
  void clear_mesh_cache();  // forget every uploaded mesh
  std::size_t cached_mesh_count() const;  // meshes uploaded and kept

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace gearsim::render
