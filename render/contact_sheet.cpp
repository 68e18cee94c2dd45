#include "render/contact_sheet.hpp"

#include <algorithm>
#include <cstring>

#include "core/errors.hpp"
#include "render/bitmap_font.hpp"

namespace gearsim::render {

Image contact_sheet(const std::vector<Image>& frames, const ContactSheetSettings& s, const std::vector<std::string>& labels) {
  if (frames.empty()) throw InputError("contact sheet: no frames");
  if (s.columns < 1) throw InputError("contact sheet: columns must be ≥ 1");
  if (s.gap_px < 0) throw InputError("contact sheet: gap_px must be ≥ 0");
  if (!labels.empty() && labels.size() != frames.size())
    throw InputError("contact sheet: " + std::to_string(labels.size()) + " labels for " + std::to_string(frames.size()) + " frames");
  const int w0 = frames.front().width_px, h0 = frames.front().height_px;
  for (std::size_t i = 0; i < frames.size(); ++i)
    if (frames[i].width_px != w0 || frames[i].height_px != h0)
      throw InputError("contact sheet: frame " + std::to_string(i) + " is " + std::to_string(frames[i].width_px) + "×" +
                       std::to_string(frames[i].height_px) + ", frame 0 is " + std::to_string(w0) + "×" + std::to_string(h0));
  const int n = static_cast<int>(frames.size());
  const int cols = std::min(s.columns, n), rows = (n + cols - 1) / cols;
  const int w = w0 / std::max(s.downscale, 1), h = h0 / std::max(s.downscale, 1);
  Image sheet(cols * w + (cols + 1) * s.gap_px, rows * h + (rows + 1) * s.gap_px, s.background);
  for (int i = 0; i < n; ++i) {
    Image cell = s.downscale == 1 ? frames[i] : downscale(frames[i], s.downscale);
    if (!labels.empty() && !labels[i].empty()) draw_overlay(cell, {labels[i]}, s.label_scale);
    const int x0 = s.gap_px + (i % cols) * (w + s.gap_px), y0 = s.gap_px + (i / cols) * (h + s.gap_px);
    for (int y = 0; y < h; ++y)
      std::memcpy(sheet.rgb.data() + (static_cast<std::size_t>(y0 + y) * sheet.width_px + x0) * 3,
                  cell.rgb.data() + static_cast<std::size_t>(y) * w * 3, static_cast<std::size_t>(w) * 3);
  }
  return sheet;
}

}  // namespace gearsim::render
