// RenderError: the machine cannot render or encode (no OSMesa core-profile context, no H.264
// encoder, an OpenGL or FFmpeg failure), with the library's own reason. Not for bad input: a bad
// resolution, an empty scene or an unwritable path is an InputError (core/errors.hpp).
#pragma once

#include <stdexcept>

namespace gearsim::render {

class RenderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace gearsim::render
