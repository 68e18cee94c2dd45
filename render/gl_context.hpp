// GlContext: one offscreen OpenGL core-profile context (OSMesa, normally Mesa's llvmpipe), checked
// when it is made: OpenGL 3.3 core or a RenderError saying what OSMesa offers instead. Owns a
// tiny default framebuffer only; frames are drawn into framebuffer objects (render_target.hpp).
// Not thread-safe: a context is current on one thread; make_current() before every use.
#pragma once

#include <memory>
#include <string>

namespace gearsim::render {

class GlContext {
 public:
  GlContext();  // throws RenderError with OSMesa's reason
  ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  void make_current();  // throws RenderError

  const std::string& version() const { return version_; }  // GL_VERSION, e.g. "4.5 (Core Profile) Mesa 22.3.6"
  const std::string& renderer() const { return renderer_; }  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  int max_samples() const { return max_samples_; }  // GL_MAX_SAMPLES
  int max_size_px() const { return max_size_px_; }  // GL_MAX_RENDERBUFFER_SIZE

 private:
  struct Handle;
  std::unique_ptr<Handle> handle_;
  std::string version_, renderer_;
  int max_samples_ = 0, max_size_px_ = 0;
};

}  // namespace gearsim::render
