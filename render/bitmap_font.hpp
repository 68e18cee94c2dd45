// A tiny built-in 5×7 bitmap font drawn straight into an Image (no GL, no font files): ASCII
// letters, digits and punctuation, plus "·", "°" and "µ" for units; anything else draws as "?".
// For frame overlays (time, speeds) and contact-sheet labels, not for typography.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "render/image.hpp"

namespace gearsim::render {

// Size of one character cell (glyph plus spacing) at scale 1, px.
inline constexpr int kGlyphCellWidth_px = 6;
inline constexpr int kGlyphCellHeight_px = 9;

// Width of `text` at `scale` (integer pixel magnification ≥ 1), px.
int text_width_px(std::string_view utf8, int scale);

// Draws `text` with its top-left glyph corner at (x_px, y_px); pixels outside are clipped.
void draw_text(Image& image, int x_px, int y_px, std::string_view utf8, int scale, Rgb colour);

// Lines of text in the top-left corner on a darkened box, white.
void draw_overlay(Image& image, const std::vector<std::string>& lines, int scale);

}  // namespace gearsim::render
