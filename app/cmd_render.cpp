// gearsim render DIR: frames and an H.264 video of a finished run, off-screen (OSMesa), replayed
// from its state.csv (app/render_run.hpp).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "app/commands.hpp"
#include "app/output_folder.hpp"
#include "input/input_limits.hpp"
#include "app/render_run.hpp"
#include "app/stop_signals.hpp"

namespace gearsim::app {

void register_render(CLI::App& app) {
  struct Options {
    std::string dir;
    physics::RenderDef def;
    double from_s = -1, to_s = -1;
  };
  auto o = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand("render", "Render a run folder off-screen: H.264 video and PNG frames of the meshing gears.");
  sub->add_option("dir", o->dir, "A folder written by `gearsim run --out`.")->required()->check(CLI::ExistingDirectory);
  sub->add_option("--camera", o->def.camera,
                  "overview, tilted, sun_mesh or ring_mesh (close-ups on the faulty planet's meshes, planet 0 without a fault).")
      ->check(CLI::IsMember({"overview", "tilted", "sun_mesh", "ring_mesh"}));
  sub->add_option("--fps", o->def.fps, "Video frames per second.")->check(CLI::Range(1, 240));
  sub->add_option("--slowmo", o->def.slowmo, "Play the simulation this many times slower (e.g. 20 to see teeth mesh).")
      ->check(input::cli_within(input::limits::kSlowMotion));
  sub->add_option("--from", o->from_s, "First simulated time, s (default: the first logged sample).")
      ->check(input::cli_within(input::limits::kRunTime_s));
  sub->add_option("--to", o->to_s, "Last simulated time, s (default: the last logged sample).")
      ->check(input::cli_within(input::limits::kRunTime_s));
  sub->add_option("--width", o->def.width_px, "Frame width, px (even).")->check(input::cli_within(input::limits::kFrameSize_px));
  sub->add_option("--height", o->def.height_px, "Frame height, px (even).")->check(input::cli_within(input::limits::kFrameSize_px));
  sub->add_option("--msaa", o->def.msaa, "Multisampling with this many samples (2 to 16) instead of the default edge anti-aliasing (0).")
      ->check(CLI::Range(0, 16))
      ->check([](const std::string& v) { return v == "1" ? std::string("one sample is no multisampling: 0 or 2 to 16") : ""; });
  sub->add_option("--png-every", o->def.png_every, "Write every Nth frame as PNG to DIR/frames/ (0: none).")->check(CLI::NonNegativeNumber);
  sub->callback([o] {
    physics::RenderDef def = o->def;
    if (o->from_s >= 0) def.from_s = o->from_s;
    if (o->to_s >= 0) def.to_s = o->to_s;
    // SIGINT or SIGTERM stops the render between two frames: no video is left half written.
    const StopSignals stop_signals;
    const OutputFolder folder(o->dir, "gearsim render");
    const RenderResult r = render_run(open_run_dir(o->dir), def, stop_signal);
    throw_if_render_stopped(r, o->dir);
    std::cout << "rendered " << r.frames << " frames of " << r.from_s << "–" << r.to_s << " s: " << r.video.string() << "\n";
  });
}

}  // namespace gearsim::app
