// gearsim render DIR: frames and an H.264 video of a finished run, off-screen (OSMesa), replayed
// from its state.csv: DIR/render_<camera>.mp4 and every Nth frame as DIR/frames/<camera>_NNNNN.png.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "app/commands.hpp"
#include "app/pose_replay.hpp"
#include "app/run_dir.hpp"
#include "app/run_scene.hpp"
#include "geometry/errors.hpp"
#include "render/png_io.hpp"
#include "render/renderer.hpp"
#include "render/video_writer.hpp"

namespace gearsim::app {
namespace {

struct RenderOptions {
  std::string dir;
  std::string camera = "overview";
  int fps = 30;
  double slowmo = 1;  // the video plays this many times slower than the simulation
  double from_s = -1, to_s = -1;
  int width = 1280, height = 720, msaa = 4;
  int png_every = 10;  // 0: no PNG frames
};

void render_run(const RenderOptions& o) {
  const RunDir run = open_run_dir(o.dir);
  const PoseReplay replay(run.scenario, read_csv(run.dir / "state.csv"));
  const double from = o.from_s < 0 ? replay.start_s() : o.from_s;
  const double to = o.to_s < 0 ? replay.end_s() : o.to_s;
  if (!(to > from)) throw InputError("--from/--to: the span " + std::to_string(from) + "–" + std::to_string(to) + " s is empty");
  if (from < replay.start_s() || to > replay.end_s())
    throw InputError("--from/--to: " + std::to_string(from) + "–" + std::to_string(to) + " s is outside the logged " +
                     std::to_string(replay.start_s()) + "–" + std::to_string(replay.end_s()) + " s");
  const double dt = 1.0 / (o.fps * o.slowmo);  // simulated seconds per frame
  const long frames = static_cast<long>(std::floor((to - from) / dt + 1e-9)) + 1;
  const RunMeshes meshes = run_meshes(run.scenario);
  render::RenderSettings rs;
  rs.width_px = o.width;
  rs.height_px = o.height;
  rs.msaa_samples = o.msaa;
  render::Renderer renderer(rs);
  const std::filesystem::path video = run.dir / ("render_" + o.camera + ".mp4");
  render::VideoWriter writer(video, {o.width, o.height, o.fps});
  if (o.png_every > 0) std::filesystem::create_directories(run.dir / "frames");
  for (long k = 0; k < frames; ++k) {
    const double t = std::min(from + static_cast<double>(k) * dt, to);  // rounding of the last frame
    const std::vector<Eigen::Isometry3d> poses = replay.poses(t);
    char line[96];
    std::snprintf(line, sizeof line, "%s  t = %.4f s  (%s, %gx slower)", run.scenario.name.c_str(), t, o.camera.c_str(), o.slowmo);
    const render::Scene scene = run_scene(meshes, poses, {line});
    const render::Image image = renderer.render(scene, run_camera(o.camera, run.scenario, scene, poses, renderer.aspect()));
    writer.add_frame(image);
    if (o.png_every > 0 && k % o.png_every == 0) {
      char name[64];
      std::snprintf(name, sizeof name, "%s_%05ld.png", o.camera.c_str(), k);
      render::write_png(image, run.dir / "frames" / name);
    }
  }
  writer.finish();
  std::cout << "rendered " << frames << " frames of " << from << "–" << to << " s: " << video.string() << "\n";
}

}  // namespace

void register_render(CLI::App& app) {
  auto o = std::make_shared<RenderOptions>();
  CLI::App* sub = app.add_subcommand("render", "Render a run folder off-screen: H.264 video and PNG frames of the meshing gears.");
  sub->add_option("dir", o->dir, "A folder written by `gearsim run --out`.")->required()->check(CLI::ExistingDirectory);
  sub->add_option("--camera", o->camera, "overview, tilted or mesh (close-up on the first sun/driver mesh).")
      ->check(CLI::IsMember({"overview", "tilted", "mesh"}));
  sub->add_option("--fps", o->fps, "Video frames per second.")->check(CLI::Range(1, 240));
  sub->add_option("--slowmo", o->slowmo, "Play the simulation this many times slower (e.g. 20 to see teeth mesh).")
      ->check(CLI::PositiveNumber);
  sub->add_option("--from", o->from_s, "First simulated time, s (default: the first logged sample).");
  sub->add_option("--to", o->to_s, "Last simulated time, s (default: the last logged sample).");
  sub->add_option("--width", o->width, "Frame width, px (even).")->check(CLI::Range(16, 4096));
  sub->add_option("--height", o->height, "Frame height, px (even).")->check(CLI::Range(16, 4096));
  sub->add_option("--msaa", o->msaa, "Multisampling (0: off).")->check(CLI::Range(0, 16));
  sub->add_option("--png-every", o->png_every, "Write every Nth frame as PNG to DIR/frames/ (0: none).")->check(CLI::NonNegativeNumber);
  sub->callback([o] { render_run(*o); });
}

}  // namespace gearsim::app
