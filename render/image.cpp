#include "render/image.hpp"

#include <algorithm>
#include <cstdlib>
#include <string>

#include "core/errors.hpp"

namespace gearsim::render {

Image::Image(int width, int height, Rgb fill) : width_px(width), height_px(height) {
  if (width < 0 || height < 0) throw InputError("image: negative size");
  rgb.resize(static_cast<std::size_t>(width) * height * 3);
  for (std::size_t i = 0; i < rgb.size(); i += 3) {
    rgb[i] = fill.r;
    rgb[i + 1] = fill.g;
    rgb[i + 2] = fill.b;
  }
}

Rgb Image::at(int x, int y) const {
  GEARSIM_CHECK(x >= 0 && y >= 0 && x < width_px && y < height_px, "pixel outside the image");
  const std::size_t i = (static_cast<std::size_t>(y) * width_px + x) * 3;
  return {rgb[i], rgb[i + 1], rgb[i + 2]};
}

void Image::set(int x, int y, Rgb c) {
  if (x < 0 || y < 0 || x >= width_px || y >= height_px) return;
  const std::size_t i = (static_cast<std::size_t>(y) * width_px + x) * 3;
  rgb[i] = c.r;
  rgb[i + 1] = c.g;
  rgb[i + 2] = c.b;
}

ImageDifference compare_images(const Image& a, const Image& b) {
  if (a.width_px != b.width_px || a.height_px != b.height_px)
    throw InputError("compare_images: sizes differ (" + std::to_string(a.width_px) + "×" + std::to_string(a.height_px) + " vs " +
                     std::to_string(b.width_px) + "×" + std::to_string(b.height_px) + ")");
  ImageDifference d;
  if (a.rgb.empty()) return d;
  double sum = 0;
  for (std::size_t i = 0; i < a.rgb.size(); ++i) {
    const int delta = std::abs(int{a.rgb[i]} - int{b.rgb[i]});
    d.max = std::max(d.max, double(delta));
    sum += delta;
  }
  d.mean = sum / double(a.rgb.size());
  return d;
}

long count_pixels_not(const Image& image, Rgb background) {
  long n = 0;
  for (std::size_t i = 0; i < image.rgb.size(); i += 3)
    if (image.rgb[i] != background.r || image.rgb[i + 1] != background.g || image.rgb[i + 2] != background.b) ++n;
  return n;
}

Image downscale(const Image& image, int factor) {
  if (factor < 1) throw InputError("downscale: factor must be ≥ 1, got " + std::to_string(factor));
  if (image.width_px % factor != 0 || image.height_px % factor != 0)
    throw InputError("downscale: " + std::to_string(image.width_px) + "×" + std::to_string(image.height_px) + " does not divide by " +
                     std::to_string(factor));
  Image out(image.width_px / factor, image.height_px / factor);
  const int n = factor * factor;
  for (int y = 0; y < out.height_px; ++y)
    for (int x = 0; x < out.width_px; ++x)
      for (int c = 0; c < 3; ++c) {
        int sum = 0;
        for (int dy = 0; dy < factor; ++dy)
          for (int dx = 0; dx < factor; ++dx)
            sum += image.rgb[(static_cast<std::size_t>(y * factor + dy) * image.width_px + x * factor + dx) * 3 + c];
        out.rgb[(static_cast<std::size_t>(y) * out.width_px + x) * 3 + c] = static_cast<std::uint8_t>((sum + n / 2) / n);
      }
  return out;
}

}  // namespace gearsim::render
