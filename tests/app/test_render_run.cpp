// Rendering a run: poses replayed from state.csv put the planets on their carrier circle at the
// logged carrier angle; `gearsim render` writes the expected number of video frames and PNGs,
// the same bytes twice, and refuses bad options by name; a signal stops it between two frames
// without leaving a half-written video.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <string>
#include <thread>

#include "app/pose_replay.hpp"
#include "app/run_dir.hpp"

namespace gearsim::app {
namespace test_render_run {

namespace fs = std::filesystem;

std::string bin() { return std::string(GEARSIM_BINARY_DIR) + "/bin/gearsim"; }

fs::path short_run() {
  static const fs::path dir = [] {
    const fs::path d = fs::temp_directory_path() / ("gearsim_render_run_" + std::to_string(getpid()));
    fs::remove_all(d);
    const std::string cmd = bin() + " run " + GEARSIM_SOURCE_DIR + "/assets/scenarios/paper_dynamics.yaml --out " + d.string() +
                            " --duration 0.02 --no-analyze > /dev/null 2>&1";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
    return d;
  }();
  return dir;
}

std::pair<int, std::string> sh(const std::string& cmd) {
  FILE* p = popen((cmd + " 2>&1").c_str(), "r");
  std::string out(8192, '\0');
  out.resize(std::fread(out.data(), 1, out.size(), p));
  return {WEXITSTATUS(pclose(p)), out};
}

std::string bytes(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

TEST(PoseReplay, PlanetsRideTheCarrierCircleAtTheLoggedCarrierAngle) {
  const RunDir run = open_run_dir(short_run());
  const input::CsvTable state = input::read_csv(run.dir / "state.csv");
  const PoseReplay replay(run.scenario, state);
  std::size_t planet = 0, carrier = 0, sun = 0;
  for (std::size_t b = 0; b < run.scenario.bodies.size(); ++b) {
    if (run.scenario.bodies[b].name == "planet_0") planet = b;
    if (run.scenario.bodies[b].name == "carrier") carrier = b;
    if (run.scenario.bodies[b].name == "sun") sun = b;
  }
  const std::vector<double>& t = state.column("time_s");
  for (std::size_t i = 0; i < t.size(); i += 7) {
    const std::vector<Eigen::Isometry3d> poses = replay.poses(t[i]);
    const Eigen::Vector3d c = poses[planet].translation();
    // Centre distance 30 mm (m(z_s + z_p)/2), planet 0 placed on +x at t = 0.
    EXPECT_NEAR(c.head<2>().norm(), 30e-3, 1e-12);
    EXPECT_NEAR(std::remainder(std::atan2(c.y(), c.x()) - state.column("carrier_angle_rad")[i], 2 * std::numbers::pi), 0.0, 1e-12);
    // The sun's frame turned by its logged angle.
    const Eigen::Vector3d x = poses[sun].rotation() * Eigen::Vector3d::UnitX();
    EXPECT_NEAR(std::remainder(std::atan2(x.y(), x.x()) - state.column("sun_angle_rad")[i], 2 * std::numbers::pi), 0.0, 1e-12);
  }
  (void)carrier;
}

TEST(RenderRun, WritesTheFramesItPromisesAndTheSameBytesTwice) {
  const fs::path dir = short_run();
  // 0.0005–0.02 s at 10 fps, 50× slower: a frame every 2 ms of simulation, 10 frames; PNG every 4th: 3.
  const std::string cmd = bin() + " render " + dir.string() + " --fps 10 --slowmo 50 --width 320 --height 180 --png-every 4";
  ASSERT_EQ(sh(cmd).first, 0);
  const std::string first = bytes(dir / "video.mp4");
  const auto [code, frames] = sh("ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames -of csv=p=0 " +
                                 (dir / "video.mp4").string());
  ASSERT_EQ(code, 0);
  EXPECT_EQ(std::stoi(frames), 10);
  // H.264, and 10 frames at 10 fps last 1 s.
  const auto [c2, info] =
      sh("ffprobe -v error -select_streams v:0 -show_entries stream=codec_name,duration -of csv=p=0 " + (dir / "video.mp4").string());
  ASSERT_EQ(c2, 0);
  EXPECT_EQ(info.substr(0, 5), "h264,") << info;
  EXPECT_NEAR(std::stod(info.substr(5)), 1.0, 1e-6) << info;
  int pngs = 0;
  for (const auto& e : fs::directory_iterator(dir / "frames"))
    pngs += e.path().extension() == ".png" && e.path().filename().string().find("_sheet") == std::string::npos;
  EXPECT_EQ(pngs, 3);
  EXPECT_TRUE(fs::exists(dir / "frames" / "overview_sheet.png"));  // the contact sheet for reports
  ASSERT_EQ(sh(cmd).first, 0);
  EXPECT_EQ(bytes(dir / "video.mp4"), first);
}

// Whether a file ends with a PNG's IEND chunk (written to its end).
bool png_complete(const fs::path& p) {
  const std::string b = bytes(p);
  static const std::string iend("IEND\xae\x42\x60\x82", 8);
  return b.size() > iend.size() && b.compare(b.size() - iend.size(), iend.size(), iend) == 0;
}

TEST(RenderRun, ASignalStopsTheRenderWithoutAHalfWrittenVideo) {
  const fs::path dir = short_run();
  fs::remove_all(dir / "frames");
  // 1 200 frames (0.02 s at 60 fps, 1 000× slower), every one a PNG: stopped after a few.
  const pid_t pid = fork();
  if (pid == 0) {
    std::freopen("/dev/null", "w", stdout);
    std::freopen("/dev/null", "w", stderr);
    execl(bin().c_str(), bin().c_str(), "render", dir.c_str(), "--fps", "60", "--slowmo", "1000", "--width", "320", "--height", "180",
          "--png-every", "1", static_cast<char*>(nullptr));
    _exit(127);
  }
  auto pngs = [&] {
    int n = 0;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(dir / "frames", ec)) n += e.path().extension() == ".png";
    return n;
  };
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(5);
  int status = 0;
  bool ended = false;  // before the signal (it should not)
  while (std::chrono::steady_clock::now() < deadline && pngs() < 3 && !ended) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    ended = waitpid(pid, &status, WNOHANG) == pid;
  }
  ASSERT_FALSE(ended) << "the render ended before the signal, exit status " << status;
  kill(pid, SIGTERM);
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 143);
  // No video, finished or partial; the frames drawn are whole PNGs, fewer than all.
  EXPECT_FALSE(fs::exists(dir / "video.mp4"));
  EXPECT_FALSE(fs::exists(dir / "video.mp4.part"));
  const int drawn = pngs();
  EXPECT_GE(drawn, 3);
  EXPECT_LT(drawn, 1200);
  for (const auto& e : fs::directory_iterator(dir / "frames")) EXPECT_TRUE(png_complete(e.path())) << e.path();
  // A render run to its end afterwards leaves the video and no partial file.
  ASSERT_EQ(sh(bin() + " render " + dir.string() + " --fps 10 --slowmo 50 --width 320 --height 180").first, 0);
  EXPECT_TRUE(fs::exists(dir / "video.mp4"));
  EXPECT_FALSE(fs::exists(dir / "video.mp4.part"));
}

TEST(RenderRun, LinksNamedLikeItsVideoAreReplacedNotFollowed) {
  // Outputs stay in the folder: a link planted as video.mp4 is replaced by the video (renamed over
  // it), one planted as video.mp4.part (a name the renderer does not write) is left alone, and
  // the file they point to outside is left as it was.
  const fs::path dir = short_run();
  const fs::path outside = fs::temp_directory_path() / ("gearsim_render_outside_" + std::to_string(getpid()));
  std::ofstream(outside) << "not the renderer's\n";
  for (const char* name : {"video.mp4", "video.mp4.part"}) {
    fs::remove(dir / name);
    fs::create_symlink(outside, dir / name);
  }
  ASSERT_EQ(sh(bin() + " render " + dir.string() + " --fps 10 --slowmo 50 --width 320 --height 180").first, 0);
  EXPECT_EQ(bytes(outside), "not the renderer's\n");
  EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(dir / "video.mp4")));
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir / "video.mp4.part")));
  fs::remove(outside);
}

TEST(RenderRun, BadOptionsAreRefusedByName) {
  const fs::path dir = short_run();
  const auto [c1, o1] = sh(bin() + " render " + dir.string() + " --camera sideways");
  EXPECT_NE(c1, 0);
  EXPECT_NE(o1.find("--camera"), std::string::npos) << o1;
  const auto [c2, o2] = sh(bin() + " render " + dir.string() + " --from 0.01 --to 0.005");
  EXPECT_EQ(c2, 2);
  EXPECT_NE(o2.find("--from/--to"), std::string::npos) << o2;
  const auto [c3, o3] = sh(bin() + " render " + dir.string() + " --from 0.01 --to 0.5");
  EXPECT_EQ(c3, 2);
  EXPECT_NE(o3.find("outside the logged"), std::string::npos) << o3;
}

}  // namespace test_render_run
}  // namespace gearsim::app
