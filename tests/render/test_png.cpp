// PNG output: the same frame gives the same bytes (no time or text chunks, fixed compression),
// bytes read back give the same pixels, and a path that cannot be written is named in the error.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/errors.hpp"
#include "geometry/planetary.hpp"
#include "render/planetary_pose.hpp"
#include "render/png_io.hpp"
#include "render/renderer.hpp"
#include "tests/render/paper_scene.hpp"

namespace gearsim::render {
namespace test_png {

// A 160×120 overview of the paper's set, from a renderer of its own.
Image paper_frame() {
  const test::PaperSet& p = test::paper_set();
  RenderSettings settings;
  settings.width_px = 160;
  settings.height_px = 120;
  Renderer renderer(settings);
  Scene scene = planetary_scene(p.meshes, kinematic_planetary_pose(p.spec, p.geometry, 0.3));
  scene.overlay_lines = {"t = 0.1 s"};
  return renderer.render(scene, overview_camera(scene_bounds(scene), renderer.aspect(), 0.5));
}

TEST(Png, SameSceneGivesTheSameBytes) {
  // Two renderers (two GL contexts, llvmpipe's threads included) and two encodings.
  EXPECT_EQ(encode_png(paper_frame()), encode_png(paper_frame()));
}

TEST(Png, BytesHoldNoTimeOrTextChunks) {
  const std::vector<std::uint8_t> bytes = encode_png(Image(8, 8, {1, 2, 3}));
  const std::string s(bytes.begin(), bytes.end());
  for (const char* chunk : {"tIME", "tEXt", "zTXt", "iTXt"}) EXPECT_EQ(s.find(chunk), std::string::npos) << chunk;
}

TEST(Png, WrittenFileReadsBackAsTheSamePixels) {
  const Image frame = paper_frame();
  const std::filesystem::path path = test::output_dir("png") / "paper_frame.png";
  write_png(frame, path);
  EXPECT_EQ(read_png(path), frame);
}

TEST(Png, UnwritableFolderIsNamedInTheError) {
  // A folder that does not exist, and a "folder" that is a regular file (refused even for root).
  const std::filesystem::path dir = test::output_dir("png");
  std::ofstream(dir / "not_a_folder") << "x";
  for (const std::filesystem::path& path : {dir / "missing" / "frame.png", dir / "not_a_folder" / "frame.png"}) {
    try {
      write_png(Image(4, 4), path);
      ADD_FAILURE() << "no error for " << path;
    } catch (const OutputError& e) {  // an output that cannot be written (core/output_file.hpp)
      EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
    }
  }
}

TEST(Png, NonPngFileIsRefused) {
  const std::filesystem::path path = test::output_dir("png") / "not.png";
  std::ofstream(path) << "not a png at all";
  EXPECT_THROW(read_png(path), InputError);
  EXPECT_THROW(read_png(test::output_dir("png") / "absent.png"), InputError);
}

}  // namespace test_png
}  // namespace gearsim::render
