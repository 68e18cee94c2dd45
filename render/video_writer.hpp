// VideoWriter: Images → an H.264 MP4 (libx264 through libavcodec, muxed by libavformat, in this
// process), yuv420p at a constant frame rate, single-threaded and bit-exact flags so the same
// frames give the same file. Not a player or a transcoder; frames must all have the writer's size.
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "render/constants.hpp"
#include "render/image.hpp"

namespace gearsim::render {

struct VideoSettings {
  int width_px = 1280;  // even (yuv420p halves the chroma)
  int height_px = 720;  // even
  int frames_per_second = 30;
  int crf = constants::kDefaultVideoCrf;  // x264 constant rate factor, 0–51
  std::string preset = constants::kDefaultVideoPreset;  // x264 preset
};

// Throws InputError naming the field: odd or non-positive size, fps outside [1, 1000], crf
// outside [0, 51], an empty preset.
void validate_video_settings(const VideoSettings& settings);

class VideoWriter {
 public:
  // Opens `path` for writing. InputError: bad settings, a path that cannot be written.
  // RenderError: no libx264 encoder in this FFmpeg, or the encoder refuses the settings.
  VideoWriter(const std::filesystem::path& path, const VideoSettings& settings);
  ~VideoWriter();  // finishes the file if finish() was not called (errors are then lost)
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;

  // Appends one frame. InputError when its size differs; RenderError when encoding fails.
  void add_frame(const Image& frame);
  // Flushes the encoder and writes the MP4 trailer; further frames are refused.
  void finish();

  int frames_written() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace gearsim::render
