// Contact sheets: frames laid out row by row with gaps, reduced on request, labelled; the built-in
// font draws inside its cells.
#include <gtest/gtest.h>

#include "core/errors.hpp"
#include "render/bitmap_font.hpp"
#include "render/contact_sheet.hpp"

namespace gearsim::render {
namespace test_contact_sheet {

std::vector<Image> coloured_frames(int n, int w, int h) {
  std::vector<Image> frames;
  for (int i = 0; i < n; ++i) frames.emplace_back(w, h, Rgb{std::uint8_t(40 * i), 100, 200});
  return frames;
}

TEST(ContactSheet, FramesFillAGridRowByRow) {
  ContactSheetSettings s;
  s.columns = 3;
  s.gap_px = 2;
  const Image sheet = contact_sheet(coloured_frames(5, 10, 6), s);
  EXPECT_EQ(sheet.width_px, 3 * 10 + 4 * 2);
  EXPECT_EQ(sheet.height_px, 2 * 6 + 3 * 2);
  // Frame 4 is the second of the second row; the gap keeps the background.
  EXPECT_EQ(sheet.at(2 + 12 + 5, 2 + 8 + 3), (Rgb{160, 100, 200}));
  EXPECT_EQ(sheet.at(1, 1), s.background);
  EXPECT_EQ(sheet.at(2 + 24 + 5, 2 + 8 + 3), s.background);  // no sixth frame
}

TEST(ContactSheet, DownscaleAveragesBlocks) {
  Image checker(4, 4);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) checker.set(x, y, (x + y) % 2 ? Rgb{200, 200, 200} : Rgb{0, 0, 0});
  ContactSheetSettings s;
  s.downscale = 2;
  s.gap_px = 0;
  const Image sheet = contact_sheet({checker}, s);
  EXPECT_EQ(sheet.width_px, 2);
  EXPECT_EQ(sheet.at(1, 1), (Rgb{100, 100, 100}));
}

TEST(ContactSheet, LabelsAreDrawnInTheirFrame) {
  ContactSheetSettings s;
  s.columns = 2;
  s.gap_px = 0;
  const std::vector<Image> frames = coloured_frames(2, 80, 20);
  const Image sheet = contact_sheet(frames, s, {"", "t = 1.5 s"});
  EXPECT_EQ(sheet.at(5, 5), frames[0].at(5, 5));  // an empty label draws nothing
  long changed = 0;
  for (int y = 0; y < 20; ++y)
    for (int x = 80; x < 160; ++x) changed += sheet.at(x, y) != frames[1].at(0, 0);
  EXPECT_GT(changed, 100);
}

TEST(ContactSheet, BadInputIsRefused) {
  EXPECT_THROW(contact_sheet({}), InputError);
  std::vector<Image> mixed = coloured_frames(2, 10, 6);
  mixed.emplace_back(12, 6);
  EXPECT_THROW(contact_sheet(mixed), InputError);
  EXPECT_THROW(contact_sheet(coloured_frames(2, 10, 6), {}, {"only one label"}), InputError);
  ContactSheetSettings s;
  s.downscale = 4;  // 10 px do not divide by 4
  EXPECT_THROW(contact_sheet(coloured_frames(1, 10, 6), s), InputError);
}

TEST(BitmapFont, TextStaysInItsCellsAndUnknownCharactersDrawAsQuestionMarks) {
  Image im(40, 12, {0, 0, 0});
  draw_text(im, 1, 1, "N·m", 1, {255, 255, 255});
  EXPECT_EQ(text_width_px("N·m", 1), 3 * kGlyphCellWidth_px);
  for (int y = 0; y < 12; ++y)
    for (int x = 1 + 3 * kGlyphCellWidth_px; x < 40; ++x) EXPECT_EQ(im.at(x, y), (Rgb{0, 0, 0}));
  Image a(8, 9, {0, 0, 0}), b(8, 9, {0, 0, 0});
  draw_text(a, 0, 0, "\u03a9", 1, {255, 255, 255});  // Ω is not in the font
  draw_text(b, 0, 0, "?", 1, {255, 255, 255});
  EXPECT_EQ(a, b);
}

}  // namespace test_contact_sheet
}  // namespace gearsim::render
