// Rendering a finished run folder (what `gearsim render` and a scenario's `render:` section do):
// poses replayed from state.csv, frames drawn off-screen, an H.264 video DIR/video.mp4 (the
// overview camera) or DIR/video_<camera>.mp4, every Nth frame as DIR/frames/<camera>_NNNNN.png
// and a contact sheet DIR/frames/<camera>_sheet.png for reports; or one frame as an image.
// Prints nothing.
#pragma once

#include <filesystem>
#include <functional>

#include "app/run_dir.hpp"
#include "render/image.hpp"

namespace gearsim::app {

struct RenderResult {
  std::filesystem::path video;
  long frames = 0;
  double from_s = 0, to_s = 0;
  // Set when `stop_requested` stopped the render (the signal it returned): `frames_drawn` of
  // `frames` were drawn, no video was written (the partial one removed), the PNG frames written so
  // far stay (each complete), no contact sheet.
  int stopped_by = 0;
  long frames_drawn = 0;
};

// InputError naming --from/--to (or render.from_s/to_s) when the span is empty or outside the
// logged one; RenderError when no OpenGL context can be created. The video is written as
// <video>.part and renamed when complete, so an interrupted or failed render leaves no video that
// looks finished. `stop_requested` (optional) is asked between frames; non-zero stops the render.
RenderResult render_run(const RunDir& run, const physics::RenderDef& settings, const std::function<int()>& stop_requested = {});

// One frame of the run at simulated time t_s, drawn as render_run draws its frames (the same
// camera, size, anti-aliasing and overlay line): render_run's frame at t_s, pixel for pixel.
// InputError naming t_s when it lies outside the logged span; RenderError as render_run.
render::Image render_run_frame(const RunDir& run, const physics::RenderDef& settings, double t_s);

}  // namespace gearsim::app
