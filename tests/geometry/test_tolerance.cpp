// Gear accuracy tolerances: the paper's equations (1)-(5) graded by DIN 3961 and ISO 1328-1 steps,
// ISO 1328-1:1995's own class-5 formulas, rounding, and input validation.
// The planet gear of the paper: m_n = 1 mm, z = 36, d = 36 mm.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/errors.hpp"
#include "geometry/tolerance.hpp"

namespace gearsim {
namespace test_tolerance {

// Hand computations below carry 4-5 significant digits: 1e-3 µm covers their last digit.
constexpr double kHandTol_um = 1e-3;
// Closed forms evaluated in double (sums and products of a few terms): 1e-9 is far above
// round-off and far below any meaningful µm.
constexpr double kExactTol = 1e-9;

ToleranceInput planet(int quality, std::optional<double> contact_ratio = std::nullopt) {
  return ToleranceInput{1.0, 36, 36.0, quality, contact_ratio};
}

// Class 5 (step 1), m = 1, d = 36, z = 36, by hand:
//  (1) f_f  = 1.5 + 0.25 (1 + 9·1)         = 4.0
//  (2) f_Hα = 2.5 + 0.25 (1 + 3·1)         = 3.5
//  (3) F_p  = 7.25 · 36^(1/3) / 36^(1/7)   = 7.25 · 3.30193 / 1.66844 = 14.3475
//  (4) F_α  = sqrt(3.5² + 4.0²)            = sqrt(28.25) = 5.31507
//  (5) F_i' = 0.8 (14.3475 + 5.31507)      = 15.7301
TEST(Tolerance, PaperClass5ValuesMatchHandComputation) {
  const ToleranceResult r = paper_tolerances(planet(5), ToleranceStandard::Din3961);
  EXPECT_NEAR(r.step_factor, 1.0, kExactTol);
  EXPECT_NEAR(r.at("profile_form").class5_um, 4.0, kExactTol);
  EXPECT_NEAR(r.at("profile_angle").class5_um, 3.5, kExactTol);
  EXPECT_NEAR(r.at("total_pitch").class5_um, 14.3475, kHandTol_um);
  EXPECT_NEAR(r.at("total_profile").class5_um, 5.31507, kHandTol_um);
  EXPECT_NEAR(r.at("single_flank_composite").class5_um, 15.7301, kHandTol_um);
}

// The paper: "43 µm for class 8". DIN step 1.4³ = 2.744; 15.7301 · 2.744 = 43.1633 → 43 µm.
TEST(Tolerance, DinClass8SingleFlankErrorIs43um) {
  const ToleranceResult r = paper_tolerances(planet(8), ToleranceStandard::Din3961);
  EXPECT_NEAR(r.step_factor, 2.744, kExactTol);
  EXPECT_NEAR(r.at("single_flank_composite").unrounded_um, 43.1633, kHandTol_um);
  ASSERT_TRUE(r.single_flank_error_um.has_value());
  EXPECT_NEAR(*r.single_flank_error_um, 43.0, kExactTol);  // rounded: exact by construction
}

// ISO step 2^(3/2) = 2.82843; 15.7301 · 2.82843 = 44.4913 → 44 µm (above 10 µm: whole µm).
TEST(Tolerance, IsoClass8PaperSingleFlankErrorIs44um) {
  const ToleranceResult r = paper_tolerances(planet(8), ToleranceStandard::Iso1328);
  EXPECT_NEAR(r.step_factor, 2.0 * std::sqrt(2.0), kExactTol);
  EXPECT_NEAR(r.at("single_flank_composite").unrounded_um, 44.4913, kHandTol_um);
  EXPECT_NEAR(*r.single_flank_error_um, 44.0, kExactTol);
}

// ISO 1328-1:1995 §6: adjacent classes differ by √2 over the whole range 0-12.
TEST(Tolerance, IsoStepIsSqrt2PerClass) {
  EXPECT_NEAR(class_step_factor(ToleranceStandard::Iso1328, 5), 1.0, kExactTol);
  for (int q = 0; q < 12; ++q) {
    const double ratio = class_step_factor(ToleranceStandard::Iso1328, q + 1) / class_step_factor(ToleranceStandard::Iso1328, q);
    EXPECT_NEAR(ratio, std::sqrt(2.0), kExactTol) << "class " << q;
  }
}

// DIN 3961: adjacent classes differ by 1.4 over the whole range 1-12.
TEST(Tolerance, DinStepIs1_4PerClass) {
  EXPECT_NEAR(class_step_factor(ToleranceStandard::Din3961, 5), 1.0, kExactTol);
  for (int q = 1; q < 12; ++q) {
    const double ratio = class_step_factor(ToleranceStandard::Din3961, q + 1) / class_step_factor(ToleranceStandard::Din3961, q);
    EXPECT_NEAR(ratio, 1.4, kExactTol) << "class " << q;
  }
}

// ISO rounding: above 10 µm to 1 µm, 5-10 µm to 0.5 µm, below 5 µm to 0.1 µm. The results are
// decimal values, so a 1e-9 µm tolerance only absorbs their binary representation.
TEST(Tolerance, IsoRoundingRules) {
  const auto iso = [](double v) { return round_tolerance_um(ToleranceStandard::Iso1328, v); };
  EXPECT_NEAR(iso(12.6), 13.0, kExactTol);
  EXPECT_NEAR(iso(10.4), 10.0, kExactTol);
  EXPECT_NEAR(iso(7.3), 7.5, kExactTol);
  EXPECT_NEAR(iso(7.2), 7.0, kExactTol);
  EXPECT_NEAR(iso(9.8), 10.0, kExactTol);
  EXPECT_NEAR(iso(5.2), 5.0, kExactTol);
  EXPECT_NEAR(iso(4.26), 4.3, kExactTol);
  EXPECT_NEAR(iso(4.94), 4.9, kExactTol);
}

// DIN rounding (our reading of DIN 3962's tables): 10 µm and above to 1 µm, below to 0.5 µm.
TEST(Tolerance, DinRoundingRules) {
  const auto din = [](double v) { return round_tolerance_um(ToleranceStandard::Din3961, v); };
  EXPECT_NEAR(din(43.1633), 43.0, kExactTol);
  EXPECT_NEAR(din(10.976), 11.0, kExactTol);
  EXPECT_NEAR(din(9.604), 9.5, kExactTol);
  EXPECT_NEAR(din(4.26), 4.5, kExactTol);
}

// ISO 1328-1:1995's own class-5 formulas, m = 1, d = 36 (√m = 1, √d = 6), by hand:
//  f_pt = 0.3 (1 + 0.4·6) + 4    = 5.02      F_p  = 0.3 + 1.25·6 + 7     = 14.8
//  F_α  = 3.2 + 0.22·6 + 0.7     = 5.22      f_fα = 2.5 + 0.17·6 + 0.5   = 4.02
//  f_Hα = 2 + 0.14·6 + 0.5       = 3.34
// Rounded at class 5: 5.0 (0.5 µm step), 15 (whole), 5.0, 4.0 and 3.3 (0.1 µm step).
TEST(Tolerance, IsoOwnClass5FormulasMatchHandComputation) {
  const ToleranceResult r = iso1328_tolerances(planet(5));
  EXPECT_NEAR(r.at("single_pitch").class5_um, 5.02, kExactTol);
  EXPECT_NEAR(r.at("total_pitch").class5_um, 14.8, kExactTol);
  EXPECT_NEAR(r.at("total_profile").class5_um, 5.22, kExactTol);
  EXPECT_NEAR(r.at("profile_form").class5_um, 4.02, kExactTol);
  EXPECT_NEAR(r.at("profile_slope").class5_um, 3.34, kExactTol);
  EXPECT_NEAR(r.at("single_pitch").value_um, 5.0, kExactTol);
  EXPECT_NEAR(r.at("total_pitch").value_um, 15.0, kExactTol);
  EXPECT_NEAR(r.at("total_profile").value_um, 5.0, kExactTol);
  EXPECT_NEAR(r.at("profile_form").value_um, 4.0, kExactTol);
  EXPECT_NEAR(r.at("profile_slope").value_um, 3.3, kExactTol);
}

// Annex A with ε_γ = 1.6: K = 0.2 (5.6)/1.6 = 0.7; f_i' = 0.7 (4.3 + 5.02 + 5.22) = 10.178;
// F_i' = 14.8 + 10.178 = 24.978. Class 8 (× 2.82843): 70.649 → 71 µm.
TEST(Tolerance, IsoOwnSingleFlankCompositeWithContactRatio) {
  const ToleranceResult r5 = iso1328_tolerances(planet(5, 1.6));
  ASSERT_TRUE(r5.composite_k.has_value());
  EXPECT_NEAR(*r5.composite_k, 0.7, kExactTol);
  EXPECT_NEAR(r5.at("tooth_to_tooth_single_flank").class5_um, 10.178, kExactTol);
  EXPECT_NEAR(r5.at("single_flank_composite").class5_um, 24.978, kExactTol);
  const ToleranceResult r8 = iso1328_tolerances(planet(8, 1.6));
  EXPECT_NEAR(r8.at("single_flank_composite").unrounded_um, 70.649, kHandTol_um);
  EXPECT_NEAR(*r8.single_flank_error_um, 71.0, kExactTol);
}

// K is 0.4 from ε_γ = 4 on, and continuous there: 0.2 (4 + 4)/4 = 0.4.
TEST(Tolerance, IsoCompositeFactorIsConstantFromContactRatio4) {
  EXPECT_NEAR(*iso1328_tolerances(planet(5, 4.0)).composite_k, 0.4, kExactTol);
  EXPECT_NEAR(*iso1328_tolerances(planet(5, 6.5)).composite_k, 0.4, kExactTol);
  EXPECT_NEAR(*iso1328_tolerances(planet(5, 3.999999)).composite_k, 0.4, 1e-6);
}

// No contact ratio: the Annex A values are left out, not computed from a guessed ε_γ.
TEST(Tolerance, IsoOwnWithoutContactRatioHasNoComposite) {
  const ToleranceResult r = iso1328_tolerances(planet(8));
  EXPECT_EQ(r.find("tooth_to_tooth_single_flank"), nullptr);
  EXPECT_EQ(r.find("single_flank_composite"), nullptr);
  EXPECT_FALSE(r.single_flank_error_um.has_value());
  EXPECT_FALSE(r.composite_k.has_value());
}

// A coarser class never allows less: unrounded values grow strictly, rounded ones never shrink.
TEST(Tolerance, TolerancesGrowWithClass) {
  for (ToleranceStandard s : {ToleranceStandard::Din3961, ToleranceStandard::Iso1328}) {
    const int first = s == ToleranceStandard::Iso1328 ? kIsoMinQuality : kDinMinQuality;
    for (int q = first; q < 12; ++q) {
      const ToleranceResult lo = paper_tolerances(planet(q), s);
      const ToleranceResult hi = paper_tolerances(planet(q + 1), s);
      for (std::size_t i = 0; i < lo.components.size(); ++i) {
        EXPECT_GT(hi.components[i].unrounded_um, lo.components[i].unrounded_um)
            << standard_key(s) << " class " << q << " " << lo.components[i].key;
        EXPECT_GE(hi.components[i].value_um, lo.components[i].value_um) << standard_key(s) << " class " << q << " " << lo.components[i].key;
      }
    }
  }
  for (int q = kIsoMinQuality; q < kIsoMaxQuality; ++q) {
    EXPECT_GT(iso1328_tolerances(planet(q + 1, 1.6)).at("single_flank_composite").unrounded_um,
              iso1328_tolerances(planet(q, 1.6)).at("single_flank_composite").unrounded_um);
  }
}

// Out-of-range input throws InputError whose message names the parameter; nothing is clamped.
void expect_rejected(const ToleranceInput& in, ToleranceStandard s, const std::string& param) {
  try {
    if (s == ToleranceStandard::Iso1328) {
      (void)iso1328_tolerances(in);
    } else {
      (void)paper_tolerances(in, s);
    }
    ADD_FAILURE() << "no InputError for " << param;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(param), std::string::npos) << e.what();
  }
}

TEST(Tolerance, OutOfRangeInputIsRejectedNamingTheParameter) {
  const auto din = ToleranceStandard::Din3961;
  const auto iso = ToleranceStandard::Iso1328;
  expect_rejected({0.3, 36, 36.0, 8, {}}, iso, "module_mm = 0.3");
  expect_rejected({80.0, 36, 2880.0, 8, {}}, iso, "module_mm = 80");
  expect_rejected({1.0, 4, 4.0, 8, {}}, iso, "reference_diameter_mm = 4");
  expect_rejected({1.0, 36, 36.0, 13, {}}, iso, "quality = 13");
  expect_rejected({1.0, 36, 36.0, -1, {}}, iso, "quality = -1");
  expect_rejected({1.0, 36, 36.0, 0, {}}, din, "quality = 0");
  expect_rejected({0.0, 36, 36.0, 8, {}}, din, "module_mm = 0");
  expect_rejected({1.0, 0, 36.0, 8, {}}, din, "teeth = 0");
  expect_rejected({1.0, 36, 30.0, 8, {}}, din, "reference_diameter_mm = 30");
  expect_rejected({1.0, 36, 36.0, 8, 0.8}, iso, "contact_ratio = 0.8");
  expect_rejected({1.0, 36, std::nan(""), 8, {}}, din, "reference_diameter_mm");
}

// The ISO set is the ISO standard's own: its validity range applies to it and to the paper's
// formulas graded by the ISO step alike.
TEST(Tolerance, IsoRangeAppliesToPaperFormulasWithIsoStep) {
  expect_rejected({0.3, 36, 36.0, 8, {}}, ToleranceStandard::Iso1328, "expected 0.5 to 70 mm");
  EXPECT_THROW((void)paper_tolerances({0.3, 36, 36.0, 8, {}}, ToleranceStandard::Iso1328), InputError);
  EXPECT_NO_THROW((void)paper_tolerances({0.3, 36, 36.0, 8, {}}, ToleranceStandard::Din3961));
}

}  // namespace test_tolerance
}  // namespace gearsim
