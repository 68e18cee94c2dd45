// Image: an 8-bit sRGB raster (RGB, rows from the top), what the renderer returns and what PNG,
// contact sheets and video take. Plus the two measurements tests make on images. Not a GPU
// texture and not linear light.
#pragma once

#include <cstdint>
#include <vector>

namespace gearsim::render {

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
  friend bool operator==(const Rgb&, const Rgb&) = default;
};

struct Image {
  int width_px = 0, height_px = 0;
  std::vector<std::uint8_t> rgb;  // width · height · 3 bytes, row-major from the top-left

  Image() = default;
  Image(int width, int height, Rgb fill = {});
  Rgb at(int x, int y) const;
  void set(int x, int y, Rgb c);  // ignores pixels outside the image
  friend bool operator==(const Image&, const Image&) = default;
};

// Per-channel absolute differences, 0–255: the largest and the mean over every channel of every
// pixel (Magnum's CompareImage measures). Throws InputError when the sizes differ.
struct ImageDifference {
  double max = 0;
  double mean = 0;
};
ImageDifference compare_images(const Image& a, const Image& b);

// Pixels whose colour differs from `background` in any channel.
long count_pixels_not(const Image& image, Rgb background);

// Box-filtered reduction by an integer factor (≥ 1); the width and height must divide by it.
Image downscale(const Image& image, int factor);

}  // namespace gearsim::render
