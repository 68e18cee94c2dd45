#include "render/gl_context.hpp"

#include <array>
#include <vector>

#include "render/constants.hpp"
#include "render/gl.hpp"
#include "render/render_error.hpp"

namespace gearsim::render {
namespace {

// OSMesa needs a colour buffer to make a context current; frames go to FBOs, so 16×16 will do.
constexpr int kDefaultBufferSize_px = 16;

std::string gl_string(GLenum name) {
  const GLubyte* s = glGetString(name);
  return s ? reinterpret_cast<const char*>(s) : "(unknown)";
}

// OSMesa has no error string: when the core context fails, describe what a default context gives.
std::string why_no_core_context() {
  OSMesaContext fallback = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
  if (!fallback) return "OSMesa cannot create any context (broken Mesa installation or out of memory)";
  std::vector<unsigned char> buffer(4 * kDefaultBufferSize_px * kDefaultBufferSize_px);
  std::string reason;
  if (OSMesaMakeCurrent(fallback, buffer.data(), GL_UNSIGNED_BYTE, kDefaultBufferSize_px, kDefaultBufferSize_px))
    reason = "OSMesa's default context offers OpenGL \"" + gl_string(GL_VERSION) + "\" on \"" + gl_string(GL_RENDERER) + "\"";
  else
    reason = "OSMesa's default context cannot be made current either";
  OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
  OSMesaDestroyContext(fallback);
  return reason + " (a gallium OSMesa with llvmpipe gives 4.5 core; check MESA_GL_VERSION_OVERRIDE and GALLIUM_DRIVER)";
}

}  // namespace

struct GlContext::Handle {
  OSMesaContext context = nullptr;
  std::vector<unsigned char> buffer;
};

GlContext::GlContext() : handle_(std::make_unique<Handle>()) {
  const std::array<int, 15> attribs = {OSMESA_FORMAT,
                                       OSMESA_RGBA,
                                       OSMESA_DEPTH_BITS,
                                       24,
                                       OSMESA_STENCIL_BITS,
                                       0,
                                       OSMESA_ACCUM_BITS,
                                       0,
                                       OSMESA_PROFILE,
                                       OSMESA_CORE_PROFILE,
                                       OSMESA_CONTEXT_MAJOR_VERSION,
                                       constants::kGlMajorVersion,
                                       OSMESA_CONTEXT_MINOR_VERSION,
                                       constants::kGlMinorVersion,
                                       0};
  handle_->context = OSMesaCreateContextAttribs(attribs.data(), nullptr);
  if (!handle_->context)
    throw RenderError("OSMesa: cannot create an OpenGL " + std::to_string(constants::kGlMajorVersion) + "." +
                      std::to_string(constants::kGlMinorVersion) +
                      " core-profile context (OSMesaCreateContextAttribs returned NULL): " + why_no_core_context());
  handle_->buffer.resize(4 * kDefaultBufferSize_px * kDefaultBufferSize_px);
  make_current();
  version_ = gl_string(GL_VERSION);
  renderer_ = gl_string(GL_RENDERER);
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples_);
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size_px_);
}

GlContext::~GlContext() {
  if (OSMesaGetCurrentContext() == handle_->context) OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
  OSMesaDestroyContext(handle_->context);
}

void GlContext::make_current() {
  if (OSMesaGetCurrentContext() == handle_->context) return;
  if (!OSMesaMakeCurrent(handle_->context, handle_->buffer.data(), GL_UNSIGNED_BYTE, kDefaultBufferSize_px, kDefaultBufferSize_px))
    throw RenderError("OSMesa: OSMesaMakeCurrent failed for the core-profile context");
}

}  // namespace gearsim::render
