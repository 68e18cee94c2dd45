// ISO 6336-1 method B stiffness against hand-evaluated values of the standard's formulas.
#include <gtest/gtest.h>

#include "core/errors.hpp"
#include "fe/iso6336_stiffness.hpp"

using namespace gearsim;
using namespace gearsim::fe;

// z20/z31, x = 0, 20°, h_fP = 1.25 m: q' = 0.04723 + 0.15551/20 + 0.25791/31 = 0.0633258 mm·µm/N,
// c'_th = 15.791 N/(mm·µm); C_B = 0.975, C_M = 0.8 → c' = 12.317 N/(mm·µm).
// Tolerance 0.01 N/(mm·µm): the hand evaluation keeps 5 significant digits.
TEST(Iso6336Stiffness, SpurPairMatchesHandEvaluation) {
  IsoPairDef d;
  EXPECT_NEAR(iso_theoretical_single_stiffness(d) / 1e9, 15.791, 0.01);
  EXPECT_NEAR(iso_single_stiffness(d) / 1e9, 12.317, 0.01);
}

// c_γα = c'(0.75 ε_α + 0.25); ε_α = 1.6 → factor 1.45 exactly (relative 1e-12: rounding only).
TEST(Iso6336Stiffness, MeshStiffnessScalesWithContactRatio) {
  IsoPairDef d;
  d.contact_ratio = 1.6;
  EXPECT_NEAR(iso_mesh_stiffness(d) / iso_single_stiffness(d), 1.45, 1e-12);
}

// An internal wheel is z_n2 = ∞: the C3 term drops, so c'_th = 1/(C1 + C2/z1) exactly.
TEST(Iso6336Stiffness, InternalWheelDropsWheelTerm) {
  IsoPairDef d;
  d.z1 = 36;
  d.z2 = -96;
  EXPECT_NEAR(iso_theoretical_single_stiffness(d), 1e9 / (0.04723 + 0.15551 / 36.0), 1e-3);
}

TEST(Iso6336Stiffness, RejectsBadInput) {
  IsoPairDef d;
  d.z1 = 2;
  EXPECT_THROW(iso_single_stiffness(d), InputError);
  d = IsoPairDef{};
  d.contact_ratio = 0.5;
  EXPECT_THROW(iso_mesh_stiffness(d), InputError);
}
