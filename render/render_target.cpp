#include "render/render_target.hpp"

#include <cstring>
#include <string>

#include "core/errors.hpp"
#include "render/render_error.hpp"

namespace gearsim::render {
namespace {

void check_complete(GLuint fbo, const char* what) {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw RenderError(std::string("OpenGL: the ") + what + " framebuffer is incomplete (glCheckFramebufferStatus " +
                      std::to_string(status) + ")");
}

// A framebuffer with a colour (and optionally depth) renderbuffer; returns the FBO.
GLuint make_fbo(int w, int h, int samples, bool depth, GLuint* colour_rb, GLuint* depth_rb, const char* what) {
  GLuint fbo = 0;
  glGenFramebuffers(1, &fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  const auto storage = [&](GLenum format) {
    if (samples > 1)
      glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, w, h);
    else
      glRenderbufferStorage(GL_RENDERBUFFER, format, w, h);
  };
  glGenRenderbuffers(1, colour_rb);
  glBindRenderbuffer(GL_RENDERBUFFER, *colour_rb);
  storage(GL_RGBA8);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, *colour_rb);
  if (depth) {
    glGenRenderbuffers(1, depth_rb);
    glBindRenderbuffer(GL_RENDERBUFFER, *depth_rb);
    storage(GL_DEPTH_COMPONENT24);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, *depth_rb);
  }
  check_complete(fbo, what);
  return fbo;
}

}  // namespace

RenderTarget::RenderTarget(int width_px, int height_px, int samples, int supersampling)
    : width_(width_px), height_(height_px), draw_width_(width_px * supersampling), draw_height_(height_px * supersampling) {
  GLuint* rb = renderbuffers_;
  draw_fbo_ = make_fbo(draw_width_, draw_height_, samples, true, &rb[0], &rb[1], "drawing");
  full_fbo_ = samples > 1 ? make_fbo(draw_width_, draw_height_, 1, false, &rb[2], nullptr, "resolve") : draw_fbo_;
  out_fbo_ = supersampling > 1 ? make_fbo(width_, height_, 1, false, &rb[3], nullptr, "output") : full_fbo_;
}

RenderTarget::~RenderTarget() {
  glDeleteRenderbuffers(4, renderbuffers_);
  if (out_fbo_ != full_fbo_) glDeleteFramebuffers(1, &out_fbo_);
  if (full_fbo_ != draw_fbo_) glDeleteFramebuffers(1, &full_fbo_);
  glDeleteFramebuffers(1, &draw_fbo_);
}

void RenderTarget::bind_for_drawing() {
  glBindFramebuffer(GL_FRAMEBUFFER, draw_fbo_);
  glViewport(0, 0, draw_width_, draw_height_);
}

Image RenderTarget::read() {
  const auto blit = [](GLuint from, GLuint to, int w0, int h0, int w1, int h1, GLenum filter) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, from);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, to);
    glBlitFramebuffer(0, 0, w0, h0, 0, 0, w1, h1, GL_COLOR_BUFFER_BIT, filter);
  };
  if (full_fbo_ != draw_fbo_) blit(draw_fbo_, full_fbo_, draw_width_, draw_height_, draw_width_, draw_height_, GL_NEAREST);
  if (out_fbo_ != full_fbo_) blit(full_fbo_, out_fbo_, draw_width_, draw_height_, width_, height_, GL_LINEAR);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, out_fbo_);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  // The renderbuffer's own layout (RGBA8) is a copy for llvmpipe; RGB makes it convert per pixel.
  rgba_.resize(std::size_t(width_) * height_ * 4);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, rgba_.data());
  Image out(width_, height_);
  // RGBA → RGB: four bytes copied per pixel, each copy's fourth byte overwritten by the next pixel.
  const std::size_t n = std::size_t(width_) * height_;
  std::uint8_t* dst = out.rgb.data();
  for (std::size_t i = 0; i + 1 < n; ++i) std::memcpy(dst + 3 * i, &rgba_[4 * i], 4);
  if (n > 0) std::memcpy(dst + 3 * (n - 1), &rgba_[4 * (n - 1)], 3);
  return out;
}

void RenderTarget::read_depth(std::vector<float>& depth) {
  GEARSIM_CHECK(draw_fbo_ == out_fbo_, "depth read-back from a multisampled or supersampled target");
  glBindFramebuffer(GL_READ_FRAMEBUFFER, draw_fbo_);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  depth.resize(std::size_t(width_) * height_);
  glReadPixels(0, 0, width_, height_, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
}

}  // namespace gearsim::render
