#include "app/render_run.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <memory>

#include "app/output_folder.hpp"
#include "app/pose_replay.hpp"
#include "app/run_scene.hpp"
#include "core/errors.hpp"
#include "render/contact_sheet.hpp"
#include "render/png_io.hpp"
#include "render/renderer.hpp"
#include "render/video_writer.hpp"
#include "core/output_file.hpp"

namespace gearsim::app {
namespace {

// The contact sheet: up to this many of the PNG frames, 4 columns, each reduced 4×.
constexpr std::size_t kSheetFrames = 8;

// The shortest text that reads back to the same double ("0.0499999999999983", not "0.050000").
std::string shortest(double v) {
  char text[32];
  const auto r = std::to_chars(text, text + sizeof text, v);
  return std::string(text, r.ptr);
}

// The renderer's settings for a run's frames. Multisampling when asked for (msaa ≥ 2 samples),
// else edge anti-aliasing: as smooth at the gears' edges and several times cheaper on llvmpipe
// (bench_render).
render::RenderSettings frame_settings(const physics::RenderDef& o) {
  render::RenderSettings rs;
  rs.width_px = o.width_px;
  rs.height_px = o.height_px;
  if (o.msaa >= 2) {
    rs.anti_aliasing = render::AntiAliasing::Multisample;
    rs.msaa_samples = o.msaa;
  }
  return rs;
}

// The frame at simulated time t: the bodies posed, the overlay line, the camera.
render::Image draw_frame(render::Renderer& renderer, const RunMeshes& meshes, const PoseReplay& replay, const RunDir& run,
                         const std::optional<input::GearTrain>& train, const physics::RenderDef& o, double t) {
  const std::vector<Eigen::Isometry3d> poses = replay.poses(t);
  char line[128];
  std::snprintf(line, sizeof line, "%s  t = %.4f s  (%s, %gx slower)", run.scenario.name.c_str(), t, o.camera.c_str(), o.slowmo);
  const render::Scene scene = run_scene(meshes, poses, {line});
  return renderer.render(scene, run_camera(o.camera, run.scenario, train, scene, poses, renderer.aspect()));
}

}  // namespace

// frames/CAMERA_NNNNN.png of frame k.
static std::string frame_name(const std::string& camera, long k) {
  char name[64];
  std::snprintf(name, sizeof name, "_%05ld.png", k);
  return camera + name;
}

render::Image render_run_frame(const RunDir& run, const physics::RenderDef& o, double t_s) {
  const PoseReplay replay(run.scenario, input::read_csv(run.dir / "state.csv"));
  if (!(t_s >= replay.start_s() && t_s <= replay.end_s()))
    throw InputError("t_s: " + shortest(t_s) + " s is outside the logged " + shortest(replay.start_s()) + "–" + shortest(replay.end_s()) +
                     " s of " + (run.dir / "state.csv").string());
  const RunMeshes meshes = run_meshes(run.scenario);
  render::Renderer renderer(frame_settings(o));
  return draw_frame(renderer, meshes, replay, run, camera_train(o.camera, run), o, t_s);
}

RenderResult render_run(const RunDir& run, const physics::RenderDef& o, const std::function<int()>& stop_requested) {
  const PoseReplay replay(run.scenario, input::read_csv(run.dir / "state.csv"));
  RenderResult r;
  r.from_s = o.from_s.value_or(replay.start_s());
  r.to_s = o.to_s.value_or(replay.end_s());
  const std::string span = std::to_string(r.from_s) + "–" + std::to_string(r.to_s) + " s";
  if (!(r.to_s > r.from_s)) throw InputError("--from/--to (render.from_s/to_s): the span " + span + " is empty");
  if (r.from_s < replay.start_s() || r.to_s > replay.end_s())
    throw InputError("--from/--to (render.from_s/to_s): " + span + " is outside the logged " + std::to_string(replay.start_s()) + "–" +
                     std::to_string(replay.end_s()) + " s");
  const double dt = 1.0 / (o.fps * o.slowmo);  // simulated seconds per frame
  r.frames = static_cast<long>(std::floor((r.to_s - r.from_s) / dt + 1e-9)) + 1;
  const RunMeshes meshes = run_meshes(run.scenario);
  const std::optional<input::GearTrain> train = camera_train(o.camera, run);
  render::Renderer renderer(frame_settings(o));
  r.video = run.dir / (o.camera == "overview" ? std::string("video.mp4") : "video_" + o.camera + ".mp4");
  // Every frame file and the video in the folder's manifest before they are written.
  std::vector<std::string> names{r.video.filename().string()};
  for (long k = 0; o.png_every > 0 && k < r.frames; k += o.png_every) names.push_back("frames/" + frame_name(o.camera, k));
  if (o.png_every > 0) names.push_back("frames/" + o.camera + "_sheet.png");
  declare_outputs(run.dir, names);
  // Written under a temporary name until complete (core/output_file.hpp); removed on the way
  // out otherwise, the earlier video of the same name left as it was until the new one replaces it.
  StagedPath part(r.video);
  std::error_code ec;
  auto writer = std::make_unique<render::VideoWriter>(part.temp(), render::VideoSettings{o.width_px, o.height_px, o.fps});
  if (o.png_every > 0) {
    make_output_dir(run.dir / "frames", ec);
    if (ec) throw InputError((run.dir / "frames").string() + ": cannot create: " + ec.message());
  }
  std::vector<render::Image> sheet;
  std::vector<std::string> labels;
  for (long k = 0; k < r.frames; ++k) {
    if (stop_requested) {
      if (const int sig = stop_requested(); sig != 0) {
        r.stopped_by = sig;
        r.frames_drawn = k;
        writer.reset();  // closes the partial file, which `part` then removes
        return r;
      }
    }
    const double t = std::min(r.from_s + static_cast<double>(k) * dt, r.to_s);  // rounding of the last frame
    const render::Image image = draw_frame(renderer, meshes, replay, run, train, o, t);
    writer->add_frame(image);
    if (o.png_every > 0 && k % o.png_every == 0) {
      render::write_png(image, run.dir / "frames" / frame_name(o.camera, k));
      if (sheet.size() < kSheetFrames && o.width_px % 4 == 0 && o.height_px % 4 == 0) {
        sheet.push_back(image);
        char label[32];
        std::snprintf(label, sizeof label, "t = %.4f s", t);
        labels.push_back(label);
      }
    }
  }
  writer->finish();
  writer.reset();
  part.commit();
  r.frames_drawn = r.frames;
  if (!sheet.empty())
    render::write_png(render::contact_sheet(sheet, {4, 4, 4, {255, 255, 255}, 1}, labels), run.dir / "frames" / (o.camera + "_sheet.png"));
  return r;
}

}  // namespace gearsim::app
