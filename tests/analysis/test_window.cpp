// Windows: coherent gain and equivalent noise bandwidth against their closed forms.
#include <gtest/gtest.h>

#include "analysis/window.hpp"
#include "core/errors.hpp"

namespace gearsim {
namespace test_window {

TEST(Window, RectangularHasUnitGainAndOneBinOfNoiseBandwidth) {
  const Window w = make_window(WindowKind::Rectangular, 1000);
  EXPECT_DOUBLE_EQ(w.coherent_gain, 1.0);
  EXPECT_DOUBLE_EQ(w.enbw_bins, 1.0);
}

TEST(Window, PeriodicHannHasGainHalfAndEnbwOneAndAHalfBins) {
  // Σ sin²(πn/N) = N/2 and Σ sin⁴(πn/N) = 3N/8 exactly for the periodic form (N ≥ 3): CG = 1/2,
  // ENBW = N·(3N/8)/(N/2)² = 1.5 bins. Tolerance: rounding of 1000 cosines.
  const Window w = make_window(WindowKind::Hann, 1000);
  EXPECT_NEAR(w.coherent_gain, 0.5, 1e-14);
  EXPECT_NEAR(w.enbw_bins, 1.5, 1e-12);
}

TEST(Window, FlatTopMatchesHeinzelsHft95) {
  // Heinzel et al. (2002), HFT95: ENBW 3.8112 bins (tabulated to 4 decimals, hence 1e-4); with
  // peak 1, CG = a0/Σa_k = 1/4.6808 = 0.21364.
  const Window w = make_window(WindowKind::FlatTop, 4096);
  EXPECT_NEAR(w.enbw_bins, 3.8112, 1e-4);
  EXPECT_NEAR(w.coherent_gain, 1.0 / 4.6807516, 1e-7);
  EXPECT_DOUBLE_EQ(w.mainlobe_halfwidth_bins, 5.0);
}

TEST(Window, EmptyOrSingleSampleTaperIsRejected) {
  EXPECT_THROW(make_window(WindowKind::Rectangular, 0), InputError);
  EXPECT_THROW(make_window(WindowKind::Hann, 1), InputError);
}

}  // namespace test_window
}  // namespace gearsim
