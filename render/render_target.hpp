// Internal to render/: the framebuffers one frame is drawn into and the read-back into an Image.
// Drawing happens at supersampling × the image size, multisampled or not; the multisampled
// buffer is resolved into a single-sampled one of the same size, which is then reduced by the
// supersampling factor (2: a bilinear blit at exactly half size, i.e. a 2×2 box filter).
// Needs a current GlContext.
#pragma once

#include "render/gl.hpp"
#include "render/image.hpp"

#include <vector>

namespace gearsim::render {

class RenderTarget {
 public:
  // samples ≤ 1: no multisampling; supersampling 1 or 2.
  RenderTarget(int width_px, int height_px, int samples, int supersampling);
  ~RenderTarget();
  RenderTarget(const RenderTarget&) = delete;
  RenderTarget& operator=(const RenderTarget&) = delete;

  void bind_for_drawing();  // binds the drawing FBO and sets the viewport
  // Resolves, reduces and reads the pixels in GL row order (bottom-up): the renderer flips y in
  // its projection so that this order is the image's top-down order.
  Image read();
  // The drawing buffer's depth values in [0, 1], rows as read() gives them; only for a target
  // drawn without multisampling or supersampling (what edge anti-aliasing needs).
  void read_depth(std::vector<float>& depth);

 private:
  int width_, height_, draw_width_, draw_height_;
  // Framebuffers: draw (maybe multisampled) → full (single-sampled, draw size) → out (image size).
  // Without multisampling draw = full; without supersampling full = out.
  GLuint draw_fbo_ = 0, full_fbo_ = 0, out_fbo_ = 0;
  GLuint renderbuffers_[4] = {0, 0, 0, 0};
  std::vector<std::uint8_t> rgba_;  // read-back buffer: GL_RGBA reads ~6× faster than GL_RGB on llvmpipe
};

}  // namespace gearsim::render
