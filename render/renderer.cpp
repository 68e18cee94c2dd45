#include "render/renderer.hpp"

#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <utility>

#include "core/errors.hpp"
#include "render/bitmap_font.hpp"
#include "render/edge_antialiasing.hpp"
#include "render/gl_context.hpp"
#include "render/gl_program.hpp"
#include "render/render_error.hpp"
#include "render/render_target.hpp"
#include "render/shading_mesh.hpp"

namespace gearsim::render {
namespace {

// Markers and arrows are smooth shapes: a wide crease angle rounds them, their caps stay sharp.
constexpr double kMarkerCreaseAngle_rad = 60.0 * std::numbers::pi / 180.0;
// Arrow shaft radius as a fraction of the marker radius.
constexpr double kShaftToMarkerRadius = 0.4;

struct GpuMesh {
  GLuint vao = 0, vbo = 0, ibo = 0;
  GLsizei index_count = 0;
  // Held so the cache key (the pointers) cannot be reused by another mesh while cached.
  std::shared_ptr<const TriMesh> mesh;
  std::shared_ptr<const std::vector<std::uint8_t>> highlight;
  std::optional<MeshEdges> edges;  // found on first use by edge anti-aliasing
};

void upload(GpuMesh& g, const ShadingMesh& m, GLenum usage) {
  if (!g.vao) {
    glGenVertexArrays(1, &g.vao);
    glGenBuffers(1, &g.vbo);
    glGenBuffers(1, &g.ibo);
    glBindVertexArray(g.vao);
    glBindBuffer(GL_ARRAY_BUFFER, g.vbo);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, g.ibo);  // recorded in the VAO
    const auto stride = static_cast<GLsizei>(sizeof(ShadedVertex));
    glEnableVertexAttribArray(kPositionAttribute);
    glVertexAttribPointer(kPositionAttribute, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(0));
    glEnableVertexAttribArray(kNormalAttribute);
    glVertexAttribPointer(kNormalAttribute, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(ShadedVertex, normal)));
    glEnableVertexAttribArray(kHighlightAttribute);
    glVertexAttribPointer(kHighlightAttribute, 1, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(ShadedVertex, highlight)));
  }
  glBindVertexArray(g.vao);
  glBindBuffer(GL_ARRAY_BUFFER, g.vbo);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(m.vertices.size() * sizeof(ShadedVertex)), m.vertices.data(), usage);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(m.indices.size() * sizeof(std::uint32_t)), m.indices.data(), usage);
  g.index_count = static_cast<GLsizei>(m.indices.size());
}

void release(GpuMesh& g) {
  glDeleteBuffers(1, &g.ibo);
  glDeleteBuffers(1, &g.vbo);
  glDeleteVertexArrays(1, &g.vao);
}

// sRGB bytes → linear light with gamma 2 (the shader's output square root undoes it exactly).
void set_colour(GLint location, Rgb c) {
  const auto lin = [](std::uint8_t v) { return (v / 255.0f) * (v / 255.0f); };
  glUniform3f(location, lin(c.r), lin(c.g), lin(c.b));
}

void set_matrix4(GLint location, const Eigen::Matrix4d& m) {
  const Eigen::Matrix4f f = m.cast<float>();
  glUniformMatrix4fv(location, 1, GL_FALSE, f.data());  // Eigen is column-major, as GL expects
}

int supersampling(const RenderSettings& s) { return s.anti_aliasing == AntiAliasing::Supersample ? 2 : 1; }
int samples(const RenderSettings& s) { return s.anti_aliasing == AntiAliasing::Multisample ? s.msaa_samples : 0; }

}  // namespace

void validate_render_settings(const RenderSettings& s) {
  const int ss = supersampling(s);
  const auto size_ok = [&](int v) { return v >= 1 && v <= constants::kMaxImageSize_px / ss; };
  if (!size_ok(s.width_px) || !size_ok(s.height_px))
    throw InputError("render settings: resolution " + std::to_string(s.width_px) + "×" + std::to_string(s.height_px) +
                     " px: width_px and height_px must lie in [1, " + std::to_string(constants::kMaxImageSize_px / ss) + "]");
  if (s.anti_aliasing == AntiAliasing::Multisample && s.msaa_samples < 2)
    throw InputError("render settings: msaa_samples must be ≥ 2 with multisampling, got " + std::to_string(s.msaa_samples));
  if (!(s.crease_angle_rad >= 0 && s.crease_angle_rad <= std::numbers::pi))
    throw InputError("render settings: crease_angle_rad must lie in [0, π]");
  if (s.text_scale < 1) throw InputError("render settings: text_scale must be ≥ 1");
}

struct Renderer::Impl {
  RenderSettings settings;
  GlContext context;  // declared first: destroyed last, after every GL object below
  std::optional<ShadingProgram> program;
  std::optional<RenderTarget> target;
  std::map<std::pair<const void*, const void*>, GpuMesh> meshes;
  GpuMesh markers;

  std::optional<MeshEdges> marker_edges;
  std::vector<WindowEdge> window_edges;  // this frame's outline edges (kept to reuse the memory)
  std::vector<float> depth;  // this frame's depth buffer, for edge anti-aliasing
  EdgeBlendBuffers blend_buffers;

  explicit Impl(const RenderSettings& s) : settings(s) {
    const int ss = supersampling(s);
    if (s.width_px * ss > context.max_size_px() || s.height_px * ss > context.max_size_px())
      throw InputError("render settings: resolution " + std::to_string(s.width_px) + "×" + std::to_string(s.height_px) +
                       " px × supersampling " + std::to_string(ss) + " exceeds the GL limit of " + std::to_string(context.max_size_px()) +
                       " px");
    if (samples(s) > context.max_samples())
      throw InputError("render settings: msaa_samples " + std::to_string(s.msaa_samples) + " exceeds the GL limit of " +
                       std::to_string(context.max_samples()) + " on " + context.renderer());
    program.emplace();
    target.emplace(s.width_px, s.height_px, samples(s), ss);
  }

  ~Impl() {
    context.make_current();
    for (auto& [key, g] : meshes) release(g);
    release(markers);
  }

  // A cached mesh only the cache still holds can never be drawn again: free it, so scenes that
  // make new meshes every frame do not pile up GPU buffers.
  void evict_orphans() {
    for (auto it = meshes.begin(); it != meshes.end();) {
      const bool orphan = it->second.mesh.use_count() == 1 && (!it->second.highlight || it->second.highlight.use_count() == 1);
      if (orphan) {
        release(it->second);
        it = meshes.erase(it);
      } else {
        ++it;
      }
    }
  }

  GpuMesh& gpu_mesh(const SceneBody& body) {
    const auto key = std::make_pair(static_cast<const void*>(body.mesh.get()), static_cast<const void*>(body.highlight.get()));
    auto it = meshes.find(key);
    if (it != meshes.end()) return it->second;
    GpuMesh& g = meshes[key];
    g.mesh = body.mesh;
    g.highlight = body.highlight;
    upload(g, shading_mesh(*body.mesh, settings.crease_angle_rad, body.highlight.get()), GL_STATIC_DRAW);
    return g;
  }

  // Spheres at the contact points (highlight 0), arrows along the forces (highlight 1).
  void upload_markers(const Scene& scene) {
    TriMesh spheres, arrows;
    for (const ContactMarker& c : scene.contacts) {
      append_mesh(spheres, sphere_mesh(c.point_m, scene.marker_radius_m));
      const Eigen::Vector3d tip = c.point_m + scene.arrow_m_per_N * c.force_N;
      append_mesh(arrows, arrow_mesh(c.point_m, tip, kShaftToMarkerRadius * scene.marker_radius_m));
    }
    const std::vector<std::uint8_t> arrow_flags(arrows.triangles.size(), 1);
    append_mesh(spheres, arrows);
    std::vector<std::uint8_t> flags(spheres.triangles.size() - arrows.triangles.size(), 0);
    flags.insert(flags.end(), arrow_flags.begin(), arrow_flags.end());
    upload(markers, shading_mesh(spheres, kMarkerCreaseAngle_rad, &flags), GL_STREAM_DRAW);
    if (settings.anti_aliasing == AntiAliasing::Edge) marker_edges = mesh_edges(spheres, kMarkerCreaseAngle_rad, &flags);
  }

  void draw(const GpuMesh& g, const Eigen::Matrix4d& model_view) {
    set_matrix4(program->model_view, model_view);
    const Eigen::Matrix3f normal = model_view.topLeftCorner<3, 3>().inverse().transpose().cast<float>();
    glUniformMatrix3fv(program->normal_matrix, 1, GL_FALSE, normal.data());
    glBindVertexArray(g.vao);
    glDrawElements(GL_TRIANGLES, g.index_count, GL_UNSIGNED_INT, nullptr);
  }

  Image render(const Scene& scene, const Camera& camera) {
    context.make_current();
    target->bind_for_drawing();
    const Rgb bg = settings.background;
    glClearColor(bg.r / 255.0f, bg.g / 255.0f, bg.b / 255.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    // TriMesh faces are counter-clockwise seen from outside: back faces are never visible.
    // The projection flips y (see below), which mirrors the winding: front faces turn clockwise.
    if (settings.cull_back_faces)
      glEnable(GL_CULL_FACE);
    else
      glDisable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glFrontFace(GL_CW);
    glUseProgram(program->id());
    const double aspect = double(settings.width_px) / settings.height_px;
    // y flipped so that GL's bottom-up rows read out as the image's top-down rows.
    const Eigen::Matrix4d flip_y = Eigen::Vector4d(1, -1, 1, 1).asDiagonal();
    const Eigen::Matrix4d projection = flip_y * projection_matrix(camera, aspect);
    set_matrix4(program->projection, projection);
    glUniform1i(program->lit, settings.lighting == Lighting::BlinnPhong ? 1 : 0);
    glUniform1i(program->orthographic, camera.projection == Projection::Orthographic ? 1 : 0);
    const Eigen::Matrix4d view = view_matrix(camera);
    // Bodies behind the markers' share of the depth range (see kMarkerDepthShare).
    glDepthRange(constants::kMarkerDepthShare, 1.0);
    for (const SceneBody& body : scene.bodies) {
      GpuMesh& g = gpu_mesh(body);
      set_colour(program->colour, body.colour);
      set_colour(program->highlight_colour, body.highlight_colour);
      draw(g, view * body.pose.matrix());
    }
    // Markers over the bodies: contacts lie between touching flanks, hidden otherwise.
    if (!scene.contacts.empty()) {
      upload_markers(scene);
      glDepthRange(0.0, constants::kMarkerDepthShare);
      set_colour(program->colour, scene.marker_colour);
      set_colour(program->highlight_colour, scene.arrow_colour);
      draw(markers, view);
    }
    glDepthRange(0.0, 1.0);
    if (const GLenum e = glGetError(); e != GL_NO_ERROR)
      throw RenderError("OpenGL error " + std::to_string(e) + " while drawing on " + context.renderer());
    const bool edge_aa = settings.anti_aliasing == AntiAliasing::Edge;
    if (edge_aa) {
      // llvmpipe rasterises on its own threads once flushed: find the outlines meanwhile.
      glFlush();
      window_edges.clear();
      EdgeProjection edge_view{projection, settings.width_px, settings.height_px, constants::kMarkerDepthShare, 1.0};
      for (const SceneBody& body : scene.bodies) {
        GpuMesh& g = gpu_mesh(body);
        if (!g.edges) g.edges = mesh_edges(*g.mesh, settings.crease_angle_rad, g.highlight.get());
        append_outline_edges(*g.edges, view * body.pose.matrix(), edge_view, window_edges);
      }
      if (!scene.contacts.empty()) {
        edge_view.depth_near = 0.0;
        edge_view.depth_far = constants::kMarkerDepthShare;
        append_outline_edges(*marker_edges, view, edge_view, window_edges);
      }
    }
    Image image = target->read();
    if (edge_aa) {
      target->read_depth(depth);
      antialias_edges(image, depth, window_edges, blend_buffers);
    }
    draw_overlay(image, scene.overlay_lines, settings.text_scale);
    evict_orphans();
    return image;
  }
};

Renderer::Renderer(const RenderSettings& settings) {
  validate_render_settings(settings);
  impl_ = std::make_unique<Impl>(settings);
}

Renderer::~Renderer() = default;

Image Renderer::render(const Scene& scene, const Camera& camera) {
  validate_scene(scene);
  validate_camera(camera);
  return impl_->render(scene, camera);
}

const RenderSettings& Renderer::settings() const { return impl_->settings; }

double Renderer::aspect() const { return double(impl_->settings.width_px) / impl_->settings.height_px; }

std::string Renderer::gl_description() const { return impl_->context.version() + " on " + impl_->context.renderer(); }

std::size_t Renderer::cached_mesh_count() const { return impl_->meshes.size(); }

void Renderer::clear_mesh_cache() {
  impl_->context.make_current();
  for (auto& [key, g] : impl_->meshes) release(g);
  impl_->meshes.clear();
}

}  // namespace gearsim::render
