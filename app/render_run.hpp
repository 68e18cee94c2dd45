// Rendering a finished run folder (what `gearsim render` and a scenario's `render:` section do):
// poses replayed from state.csv, frames drawn off-screen, an H.264 video DIR/video.mp4 (the
// overview camera) or DIR/video_<camera>.mp4, every Nth frame as DIR/frames/<camera>_NNNNN.png
// and a contact sheet DIR/frames/<camera>_sheet.png for reports. Prints nothing.
#pragma once

#include <filesystem>

#include "app/run_dir.hpp"

namespace gearsim::app {

struct RenderResult {
  std::filesystem::path video;
  long frames = 0;
  double from_s = 0, to_s = 0;
};

// InputError naming --from/--to (or render.from_s/to_s) when the span is empty or outside the
// logged one; RenderError when no OpenGL context can be created.
RenderResult render_run(const RunDir& run, const physics::RenderDef& settings);

}  // namespace gearsim::app
