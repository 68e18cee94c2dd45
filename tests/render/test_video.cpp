// MP4 output: H.264 in an MP4 with the right frame count, frame rate and duration (checked by
// ffprobe, skipped only when ffprobe is absent), the same frames give the same bytes, and bad
// settings or paths are refused by name.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <regex>
#include <string>

#include "core/errors.hpp"
#include "render/bitmap_font.hpp"
#include "render/video_writer.hpp"
#include "tests/render/paper_scene.hpp"

namespace gearsim::render {
namespace test_video {

constexpr int kFrames = 12;
constexpr int kFps = 12;

VideoSettings small_video() {
  VideoSettings s;
  s.width_px = 160;
  s.height_px = 120;
  s.frames_per_second = kFps;
  s.preset = "veryfast";
  return s;
}

// A moving bar and the frame number: every frame differs.
Image frame(int i) {
  Image im(160, 120, {20, 30, 40});
  for (int y = 40; y < 80; ++y)
    for (int x = 10 * i; x < 10 * i + 20; ++x) im.set(x, y, {230, 120, 30});
  draw_text(im, 4, 4, "frame " + std::to_string(i), 1, {255, 255, 255});
  return im;
}

std::filesystem::path write_video(const std::string& name) {
  const std::filesystem::path path = test::output_dir("video") / name;
  VideoWriter writer(path, small_video());
  for (int i = 0; i < kFrames; ++i) writer.add_frame(frame(i));
  writer.finish();
  EXPECT_EQ(writer.frames_written(), kFrames);
  return path;
}

std::string run(const std::string& command) {
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  std::string out;
  char buf[256];
  while (pipe && fgets(buf, sizeof buf, pipe.get())) out += buf;
  return out;
}

// "key": value (quoted or not) from ffprobe's JSON.
std::string json_value(const std::string& json, const std::string& key) {
  std::smatch m;
  return std::regex_search(json, m, std::regex("\"" + key + "\": \"?([^\",\\n]*)\"?")) ? m[1].str() : "";
}

TEST(Video, Mp4HasTheFramesRateDurationAndH264) {
  if (run("command -v ffprobe").empty()) GTEST_SKIP() << "ffprobe not installed";
  const std::filesystem::path path = write_video("bar.mp4");
  const std::string json =
      run("ffprobe -v error -select_streams v:0 -count_frames -show_entries "
          "stream=codec_name,nb_read_frames,r_frame_rate,duration,pix_fmt -of json '" +
          path.string() + "'");
  EXPECT_EQ(json_value(json, "codec_name"), "h264") << json;
  EXPECT_EQ(json_value(json, "nb_read_frames"), std::to_string(kFrames)) << json;
  EXPECT_EQ(json_value(json, "r_frame_rate"), std::to_string(kFps) + "/1") << json;
  EXPECT_EQ(json_value(json, "pix_fmt"), "yuv420p") << json;
  // Constant frame rate: 12 frames at 12 fps last 1 s (MP4 time base rounding: 1 ms).
  EXPECT_NEAR(std::stod(json_value(json, "duration")), double(kFrames) / kFps, 1e-3) << json;
}

TEST(Video, SameFramesGiveTheSameBytes) {
  const auto bytes = [](const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  };
  EXPECT_EQ(bytes(write_video("a.mp4")), bytes(write_video("b.mp4")));
}

TEST(Video, UnwritablePathIsNamedInTheError) {
  const std::filesystem::path path = test::output_dir("video") / "missing" / "x.mp4";
  try {
    VideoWriter writer(path, small_video());
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
}

TEST(Video, OddSizeAndWrongFrameSizeAreRefused) {
  VideoSettings s = small_video();
  s.width_px = 161;
  EXPECT_THROW(VideoWriter(test::output_dir("video") / "odd.mp4", s), InputError);
  VideoWriter writer(test::output_dir("video") / "wrong_frame.mp4", small_video());
  EXPECT_THROW(writer.add_frame(Image(80, 60)), InputError);
}

}  // namespace test_video
}  // namespace gearsim::render
