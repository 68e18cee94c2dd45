// Contact sheet: N frames of one size laid out in a grid on one Image (row by row), optionally
// reduced and labelled, for reports. Not a layout engine: every frame has the same size.
#pragma once

#include <string>
#include <vector>

#include "render/image.hpp"

namespace gearsim::render {

struct ContactSheetSettings {
  int columns = 4;
  int gap_px = 4;  // between frames and around the sheet
  int downscale = 1;  // each frame reduced by this integer factor (box filter)
  Rgb background{255, 255, 255};
  int label_scale = 1;  // font magnification of the labels
};

// Labels (none, or one per frame; "" draws nothing) go in each frame's top-left corner. Throws InputError:
// no frames, frames of different sizes, a label count that is neither 0 nor the frame count,
// columns < 1, gap < 0, a downscale factor the frame size does not divide by.
Image contact_sheet(const std::vector<Image>& frames, const ContactSheetSettings& settings = {},
                    const std::vector<std::string>& labels = {});

}  // namespace gearsim::render
