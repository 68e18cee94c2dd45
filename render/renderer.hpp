// Renderer: draws a Scene through a Camera into an Image, offscreen (OSMesa, OpenGL 3.3 core),
// with Blinn–Phong shading (key + fill light), crease-angle normals and MSAA or supersampling.
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
  None,        // each body in its exact base colour (coverage and silhouette measurements)
};

struct RenderSettings {
  int width_px = 1280;
  int height_px = 720;
  // Anti-aliasing: multisampling (0 or 1: off) and/or supersampling (1: off, 2: drawn at twice
  // the width and height and box-filtered down). On llvmpipe MSAA 4× costs a fixed ~25 ms per
  // 1280×720 frame (clear and resolve), supersampling 2× scales with the covered pixels: the
  // latter is faster for the overview, slower for a full-frame close-up (bench_render).
  int msaa_samples = constants::kDefaultMsaaSamples;
  int supersampling = 1;
  Rgb background{28, 31, 38};
  Lighting lighting = Lighting::BlinnPhong;
  double crease_angle_rad = constants::kDefaultCreaseAngle_rad;  // 0: flat (face) normals
  int text_scale = 2;                                             // overlay font magnification
  // Skip triangles facing away from the camera: right for closed, outward-oriented meshes (every
  // TriMesh of the geometry pipeline), about half the rasterisation work. Off for open meshes.
  bool cull_back_faces = true;
};

// Throws InputError naming the field: width/height outside [1, kMaxImageSize_px] (after
// supersampling), negative MSAA samples, supersampling other than 1 or 2, a crease angle outside
// [0, π], a text scale < 1.
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
  double aspect() const;              // width / height
  std::string gl_description() const;  // GL_VERSION on GL_RENDERER
  void clear_mesh_cache();            // forget every uploaded mesh
  std::size_t cached_mesh_count() const;  // meshes uploaded and kept

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace gearsim::render
