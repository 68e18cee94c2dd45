// FE mesh stiffness of one spur pair (z 20/31, m = 1 mm, b = 10 mm, 20 µm backlash per flank) at
// 0.4 mm flank size, against the potential-energy model and the pinion's torque balance; and the
// placement geometry. The ccx cases solve two positions (~20 s each on one core)
// and are skipped when ccx is absent.
//
// Why 0.4 mm and not coarser: the mesh boundary is straight chords between nodes on the exact
// outline. At 0.8 mm the chords of the pinion's flanks near its root and of the root fillets sit
// 20–70 µm off the curves, far more than the teeth deflect at ~100 N/mm (~8 µm): the second pair
// of the two-pair zone never touches and fillet chords touch outside the path of contact
// (docs/fe-results.md, "Spur pair"). At 0.4 mm the pitch point is clean and the two-pair zone has
// positions where both pairs' boundaries touch within 0.3 µm.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <utility>

#include "core/errors.hpp"
#include "fe/process.hpp"
#include "fe/spur_pair_fe.hpp"

using namespace gearsim;
using namespace gearsim::fe;
namespace fs = std::filesystem;

namespace test_spur_pair_fe {

constexpr double kFlankSize_m = 0.4e-3;
// Candidate roll lengths scanned in the two-pair zone for the two-pair position (geometry only).
constexpr int kTwoPairCandidates = 48;
// Largest mesh-boundary gap a pair of the two-pair position may have, m: a third of one pair's
// deflection at the low load stage (~106 N over ~1.3e8 N/m ≈ 0.8 µm), so both pairs carry load at
// both stages and the secant measures two pairs, not a chord gap closing.
constexpr double kTwoPairGap_m = 0.3e-6;

SpurPairFeDef make_def() {
  SpurPairFeDef d;  // z 20/31, m 1 mm, 20°, b 10 mm, 20 µm per flank, bores half the root diameter
  d.sizing.flank_size_m = kFlankSize_m;
  return d;
}

double largest_gap(const SpurPairPlacement& p) {
  double g = 0;
  for (const auto& s : p.slots)
    if (s.on_path) g = std::max(g, s.fe_gap_m);
  return g;
}

// The roll in the two-pair zone [start, end − p_b] whose pairs' boundaries touch most closely.
double two_pair_roll(const SpurPairFeDef& d, const SpurPairMeshes& m) {
  const SpurPairPath path = spur_pair_path(d.pair);
  const double lo = path.start_roll_m, hi = path.end_roll_m - path.base_pitch_m;
  double best = lo, best_gap = INFINITY;
  for (int i = 0; i < kTwoPairCandidates; ++i) {
    const double roll = lo + (i + 0.5) * (hi - lo) / kTwoPairCandidates;
    const double g = largest_gap(place_spur_pair(d.pair, m.pinion.mesh, m.wheel.mesh, roll));
    if (g < best_gap) best_gap = g, best = roll;
  }
  return best;
}

// One folder per process: ctest runs the cases of this file as separate processes at once, and
// several of them solve the same position.
fs::path work_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("gearsim_fe_spur_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  return d;
}

// Standard gears with every flank thinned by t: at the kinematic position each side has 2t of
// clearance along the line of action, so the wheel turns 2t / r_b2 to touch the pinion's driving
// flank, wherever the contact is. Tolerance 0.5 %: the flank tables resolve ~2 nm against 40 µm.
TEST(SpurPairPlacement, ExactClosingEqualsTheBacklash) {
  const SpurPairFeDef d = make_def();
  const SpurPairMeshes m = mesh_spur_pair(d);
  const SpurPairPath path = spur_pair_path(d.pair);
  for (double roll : rolls_over_base_pitch(path, 3)) {
    const SpurPairPlacement p = place_spur_pair(d.pair, m.pinion.mesh, m.wheel.mesh, roll);
    EXPECT_NEAR(p.wheel_closing_exact_rad * path.wheel_base_radius_m / (2 * d.pair.thinning_per_flank_m), 1.0, 5e-3) << "roll " << roll;
  }
}

TEST(SpurPairFe, RejectsBadInput) {
  auto expect_error = [](const SpurPairFeDef& d, const std::string& field) {
    try {
      validate_spur_pair_fe(d);
      ADD_FAILURE() << "accepted a bad " << field;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
  };
  SpurPairFeDef d = make_def();
  d.pair.thinning_per_flank_m = 0;
  expect_error(d, "thinning_per_flank_m");
  d = make_def();
  d.pair.bore_over_root = 1.0;
  expect_error(d, "bore_over_root");
  d = make_def();
  d.pinion_torque_N_m = -1;
  expect_error(d, "pinion_torque_N_m");
  d = make_def();
  d.element_type = "C3D8";
  expect_error(d, "element_type");
  // A roll length off the path of contact names the path.
  d = make_def();
  const SpurPairMeshes m = mesh_spur_pair(d);
  try {
    place_spur_pair(d.pair, m.pinion.mesh, m.wheel.mesh, spur_pair_path(d.pair).end_roll_m + 1e-4);
    ADD_FAILURE() << "accepted a roll beyond the pinion tip";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("path of contact"), std::string::npos) << e.what();
  }
}

// The ccx cases' solves, each made once per process and only when a test asks for it (ctest runs
// every test in its own process): the pitch point (one pair in contact: ε_α = 1.61 and the pitch
// point lies in the single-contact zone [end − p_b, start + p_b]) and a two-pair position.
class SpurPairFeSolved : public ::testing::Test {
 protected:
  void SetUp() override {
    if (find_executable("ccx").empty()) GTEST_SKIP() << "ccx not installed";
  }
  static const SpurPairFeDef& def() {
    static const SpurPairFeDef d = make_def();
    return d;
  }
  static const SpurPairPath& path() {
    static const SpurPairPath p = spur_pair_path(def().pair);
    return p;
  }
  static const SpurPairMeshes& meshes() {
    static const SpurPairMeshes m = mesh_spur_pair(def());
    return m;
  }
  static const SpurPairFePosition& pitch() {
    static const SpurPairFePosition p = solve_spur_pair_position(def(), meshes(), path().pitch_roll_m, work_dir("pitch"));
    return p;
  }
  // The two-pair roll and the largest mesh-boundary gap of its pairs, m.
  static const std::pair<double, double>& two_roll_gap() {
    static const std::pair<double, double> rg = [] {
      const double roll = two_pair_roll(def(), meshes());
      return std::pair{roll, largest_gap(place_spur_pair(def().pair, meshes().pinion.mesh, meshes().wheel.mesh, roll))};
    }();
    return rg;
  }
  static const SpurPairFePosition& two() {
    static const SpurPairFePosition p = solve_spur_pair_position(def(), meshes(), two_roll_gap().first, work_dir("two"));
    return p;
  }
};

// At the pitch point one pair carries the torque: contact force = T / r_b1 at both load stages.
// Tolerance from the geometry, not chosen: the FE contact normal is a chord's, tilted from the
// involute's by up to L / (2ρ) (L the flank element size, ρ = 3.42 mm the pinion flank's radius
// of curvature there), and stick friction tilts the force by up to atan μ; either tilt changes the
// force's lever arm about the pinion by tan α per radian: tan α (L / (2ρ) + μ) = 3.2 %.
TEST_F(SpurPairFeSolved, PitchPointOnePairCarriesTheTorque) {
  const SpurPairFePosition& p = pitch();
  EXPECT_EQ(p.loaded_pairs, 1);
  const double tol = std::tan(def().pair.pressure_angle_rad) * (kFlankSize_m / (2 * path().pitch_roll_m) + def().friction);
  const double rb1 = path().pinion_base_radius_m;
  EXPECT_NEAR(p.contact_force_low_N * rb1 / p.torque_low_N_m, 1.0, tol);
  EXPECT_NEAR(p.contact_force_full_N * rb1 / p.torque_full_N_m, 1.0, tol);
}

// Single-pair stiffness at the pitch point against the potential-energy model at the same contact
// point, within the 15 %. This, not the ISO band, is the check: the PE value is for the
// same contact point and the same bodies, while ISO's c' is one number per pair with empirical
// factors, and the FE value at one position moves by ±8 % with where the contact falls between
// nodes (docs/fe-results.md: 12.96–15.07 N/(mm·µm) over the single-contact zone at 0.2 mm). The FE
// stiffness is taken with its gear bodies: Sainsot's fillet-foundation term of the PE model, with
// h_f = r_f / r_bore of these gears, already holds the bodies' torsion (its compliance grows with
// h_f as the annulus torsion r_b²(1/r_bore² − 1/r_f²)/(4πGb) does: +1.345e-9 vs +1.364e-9 m/N
// from h_f = 2 to 4 on this pinion), so nothing is subtracted here.
TEST_F(SpurPairFeSolved, PitchPointStiffnessWithinPotentialEnergyBand) {
  const SpurPairFePosition& p = pitch();
  ASSERT_EQ(p.pe_pairs, 1);
  EXPECT_NEAR(p.stiffness_N_per_m / p.pe_stiffness_N_per_m, 1.0, 0.15)
      << "FE " << p.stiffness_N_per_m << " N/m, PE " << p.pe_stiffness_N_per_m << " N/m";
}

// The ISO check: the single-pair stiffness at the pitch point per face width lies in the
// ISO 6336-1 band between c' (method B with the empirical C_M = 0.8, C_B = 0.975: 12.32
// N/(mm·µm) for z20/31) and the theoretical c'_th (15.79), bodies included as in a real pair.
TEST_F(SpurPairFeSolved, PitchPointStiffnessWithinTheIsoBand) {
  const SpurPairReferences ref = spur_pair_references(def().pair);
  const double c = pitch().stiffness_N_per_m / def().pair.face_width_m;
  EXPECT_GT(c, ref.iso_single_N_per_m2) << "c = " << c * 1e-9 << " N/(mm·µm)";
  EXPECT_LT(c, ref.iso_single_theory_N_per_m2) << "c = " << c * 1e-9 << " N/(mm·µm)";
}

// Where two pairs are in contact the mesh is stiffer than with one, both pairs carrying load. The
// threshold 1.3 is the issue's. The PE model gives 1.72 (1.59 with the gear bodies' torsion once
// in series with both pairs instead of once per pair); the FE gives 1.45 at this size and
// 1.22–1.31 against the pitch point at 0.2 mm (docs/fe-results.md), so this guards the load sharing at
// 0.4 mm, not a converged ratio. The position is the two-pair roll whose mesh
// boundaries touch most closely (a chord gap of a few µm would keep the second pair unloaded at
// the low stage: a discretisation artefact, not physics).
TEST_F(SpurPairFeSolved, TwoPairsStifferThanOne) {
  ASSERT_LT(two_roll_gap().second, kTwoPairGap_m) << "no two-pair position with closely touching boundaries";
  EXPECT_EQ(two().pe_pairs, 2);
  EXPECT_EQ(two().loaded_pairs, 2);
  EXPECT_GT(two().stiffness_N_per_m / pitch().stiffness_N_per_m, 1.3)
      << "two pairs " << two().stiffness_N_per_m << " N/m at roll " << two().roll_m << " m, one pair " << pitch().stiffness_N_per_m
      << " N/m";
}

}  // namespace test_spur_pair_fe
