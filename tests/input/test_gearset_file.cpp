// Gear-set spec files: the paper's spec parses to the paper's gears; every bad input is refused
// with the file, line and key.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "input/gearset_file.hpp"
#include "core/errors.hpp"

namespace gearsim::input {
namespace test_gearset_file {

const std::string kPaperSpec = std::string(GEARSIM_SOURCE_DIR) + "/assets/specs/paper_gearset.yaml";

TEST(GearSetFile, PaperSpecDescribesThePapersPlanetarySet) {
  const GearSetFile f = load_gearset(kPaperSpec);
  ASSERT_TRUE(f.planetary.has_value());
  EXPECT_EQ(f.planetary->sun.teeth, 24);
  EXPECT_EQ(f.planetary->planet.teeth, 36);
  EXPECT_EQ(f.planetary->ring.teeth, 96);
  EXPECT_EQ(f.planetary->planets, 3);
  EXPECT_EQ(f.planetary->ring.kind, GearKind::Internal);
  // Defaults reach every gear: m = 1 mm, α = 20° (parsed from degrees), b = 10 mm.
  for (const GearSpec& g : f.gears) {
    EXPECT_DOUBLE_EQ(g.module_m, 1e-3);
    EXPECT_NEAR(g.pressure_angle_rad, 20.0 * std::numbers::pi / 180.0, 1e-15);
    EXPECT_DOUBLE_EQ(g.face_width_m, 10e-3);
  }
  const GearSpec& faulty = f.gear("planet_faulty");
  ASSERT_EQ(faulty.errors.flank_offsets.size(), 1u);
  EXPECT_DOUBLE_EQ(faulty.errors.flank_offsets[0].normal_offset_m, -43e-6);
  EXPECT_EQ(faulty.errors.flank_offsets[0].flank, Flank::Ccw);
  EXPECT_EQ(f.tolerance_quality, 8);
}

// Writes `text` to a temp file and returns the error message load_gearset gives for it.
std::string error_for(const std::string& text) {
  const std::filesystem::path p =
      std::filesystem::temp_directory_path() / ("gearsim_spec_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                                                ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".yaml");
  { std::ofstream(p) << text; }
  try {
    load_gearset(p);
  } catch (const InputError& e) {
    std::filesystem::remove(p);
    return e.what();
  }
  std::filesystem::remove(p);
  return "";
}

const std::string kGood =
    "name: t\n"
    "density_kg_m3: 7850\n"
    "gears:\n"
    "  pinion: {kind: external, teeth: 20, module_m: 0.002, face_width_m: 0.01}\n"
    "  wheel: {kind: external, teeth: 40, module_m: 0.002, face_width_m: 0.01}\n"
    "train: {type: pair, driver: pinion, driven: wheel}\n";

TEST(GearSetFile, GoodPairParses) { EXPECT_EQ(error_for(kGood), ""); }

TEST(GearSetFile, UnknownKeyIsAnErrorWithItsLine) {
  std::string text = kGood + "colour: blue\n";
  const std::string e = error_for(text);
  EXPECT_NE(e.find(":7:"), std::string::npos) << e;  // line 7 holds the stray key
  EXPECT_NE(e.find("colour: unknown key"), std::string::npos) << e;
}

TEST(GearSetFile, UnknownKeyInsideAGearNamesItsPath) {
  std::string text = kGood;
  text.replace(text.find("teeth: 20"), 9, "teeth: 20, tooth_count: 3");
  const std::string e = error_for(text);
  EXPECT_NE(e.find("gears.pinion.tooth_count: unknown key"), std::string::npos) << e;
}

TEST(GearSetFile, WrongTypeSaysWhatWasExpected) {
  std::string text = kGood;
  text.replace(text.find("teeth: 40"), 9, "teeth: forty");
  const std::string e = error_for(text);
  EXPECT_NE(e.find("gears.wheel.teeth: expected an integer, got 'forty'"), std::string::npos) << e;
}

TEST(GearSetFile, MissingRequiredKeyIsNamed) {
  std::string text = kGood;
  text.replace(text.find("module_m: 0.002, face_width_m"), 16, "");
  const std::string e = error_for(text);
  EXPECT_NE(e.find("gears.pinion.module_m: missing"), std::string::npos) << e;
}

TEST(GearSetFile, TrainNamingAMissingGearIsRefused) {
  std::string text = kGood;
  text.replace(text.find("driven: wheel"), 13, "driven: gear9");
  const std::string e = error_for(text);
  EXPECT_NE(e.find("train.driven: no gear named 'gear9'"), std::string::npos) << e;
}

TEST(GearSetFile, AngleGivenTwiceIsRefused) {
  std::string text = kGood;
  text.replace(text.find("teeth: 20"), 9, "teeth: 20, pressure_angle_deg: 20, pressure_angle_rad: 0.3");
  EXPECT_NE(error_for(text).find("give the angle once"), std::string::npos);
}

TEST(GearSetFile, ImpossibleGearNamesTheGearAndField) {
  std::string text = kGood;
  text.replace(text.find("teeth: 20"), 9, "teeth: 2");
  const std::string e = error_for(text);
  // file:line:column, then the key path of the gear and field, then what was expected.
  EXPECT_NE(e.find(".yaml:4:"), std::string::npos) << e;
  EXPECT_NE(e.find("gears.pinion.teeth: expected a number of teeth in [3, "), std::string::npos) << e;
  EXPECT_NE(e.find("got 2"), std::string::npos) << e;
}

// kGood with `from` (in the pinion's line, line 4) replaced by `to`.
std::string pinion_with(const std::string& from, const std::string& to) {
  std::string text = kGood;
  const std::size_t at = text.find(from, text.find("pinion:"));
  return text.replace(at, from.size(), to);
}

TEST(GearSetFile, AModuleOrFaceWidthOf1e300IsRefusedWithItsRange) {
  // Unchecked, either overflows the outline's tessellation: an internal error, not a refusal.
  std::string e = error_for(pinion_with("module_m: 0.002", "module_m: 1.0e300"));
  EXPECT_NE(e.find(".yaml:4:"), std::string::npos) << e;
  EXPECT_NE(e.find("gears.pinion.module_m: expected a module in [1e-05, 0.1] m, got 1e+300"), std::string::npos) << e;
  e = error_for(pinion_with("face_width_m: 0.01", "face_width_m: 1.0e300"));
  EXPECT_NE(e.find(".yaml:4:"), std::string::npos) << e;
  EXPECT_NE(e.find("gears.pinion.face_width_m: expected a face width in [1e-05, 2] m, got 1e+300"), std::string::npos) << e;
}

TEST(GearSetFile, EveryNumberOfAGearIsCheckedAgainstItsLimit) {
  struct Case {
    std::string key_value, expected;
  };
  const Case cases[] = {
      {"pressure_angle_deg: 60", "gears.pinion.pressure_angle_deg: expected a pressure angle in (0, 45) °, got 60"},
      {"pressure_angle_rad: 1e300", "gears.pinion.pressure_angle_rad: expected a pressure angle in (0, 0.785398) rad"},
      {"profile_shift: 1e300", "gears.pinion.profile_shift: expected a profile shift coefficient (in modules) in [-3, 3]"},
      {"addendum_coeff: 1e300", "gears.pinion.addendum_coeff: expected a tooth depth factor (in modules) in [0, 3]"},
      {"dedendum_coeff: -1", "gears.pinion.dedendum_coeff: expected a tooth depth factor (in modules) in [0, 3], got -1"},
      {"root_fillet_coeff: 1e300", "gears.pinion.root_fillet_coeff: expected a root fillet factor (in modules) in [0, 1]"},
      {"thinning_per_flank_m: 1e300", "gears.pinion.thinning_per_flank_m: expected a thinning per flank in [0, 0.001] m"},
      {"bore_diameter_m: 1e300", "gears.pinion.bore_diameter_m: expected a diameter in [0, 100] m, got 1e+300"},
      {"tooth0_angle_deg: 1e300", "gears.pinion.tooth0_angle_deg: expected an angle in [-360, 360] °, got 1e+300"},
      {"errors: {flank_offsets: [{tooth: 0, flank: ccw, normal_offset_m: 1e300}]}",
       "gears.pinion.errors.flank_offsets[0].normal_offset_m: expected a tooth error in [-0.001, 0.001] m"},
      {"errors: {pitch_errors: [{tooth: 0, error_m: -1e300}]}", "gears.pinion.errors.pitch_errors[0].error_m: expected a tooth error"},
      {"errors: {profile_slopes: [{flank: cw, slope_m: 1e300}]}", "gears.pinion.errors.profile_slopes[0].slope_m: expected a tooth error"},
      {"errors: {eccentricity: {eccentricity_m: 1e300}}",
       "gears.pinion.errors.eccentricity.eccentricity_m: expected an eccentricity in [0, 0.01] m"},
      {"errors: {eccentricity: {eccentricity_m: 1e-5, phase_rad: 1e300}}", "gears.pinion.errors.eccentricity.phase_rad: expected an angle"},
  };
  for (const Case& c : cases) {
    const std::string e = error_for(pinion_with("teeth: 20", "teeth: 20, " + c.key_value));
    EXPECT_NE(e.find(".yaml:4:"), std::string::npos) << c.key_value << ": " << e;
    EXPECT_NE(e.find(c.expected), std::string::npos) << c.key_value << ": " << e;
  }
}

TEST(GearSetFile, AValueFromTheDefaultsBlockIsCheckedWhereItStands) {
  std::string text = kGood;
  text.replace(text.find("gears:\n"), 7, "defaults: {profile_shift: 1e300}\ngears:\n");
  const std::string e = error_for(text);
  EXPECT_NE(e.find(".yaml:3:"), std::string::npos) << e;
  EXPECT_NE(e.find("defaults.profile_shift: expected a profile shift coefficient"), std::string::npos) << e;
}

TEST(GearSetFile, DensityAndToleranceClassAreBounded) {
  std::string text = kGood;
  std::string e = error_for(text.replace(text.find("7850"), 4, "1e300"));
  EXPECT_NE(e.find(".yaml:2:"), std::string::npos) << e;
  EXPECT_NE(e.find("density_kg_m3: expected a density in [1, 100000] kg/m³, got 1e+300"), std::string::npos) << e;
  e = error_for(kGood + "tolerance: {quality: 99}\n");
  EXPECT_NE(e.find("tolerance.quality: expected a quality class in [0, 12], got 99"), std::string::npos) << e;
}

TEST(GearSetFile, ANameThatIsNotUtf8IsRefusedNamingTheKey) {
  std::string text = kGood;
  const std::string e = error_for(text.replace(0, 7, "name: \"t\xff\"\n"));
  EXPECT_NE(e.find(".yaml:1:"), std::string::npos) << e;
  EXPECT_NE(e.find("name: expected UTF-8 text, got 't\\xFF' (invalid byte 0xFF at byte 2)"), std::string::npos) << e;
}

TEST(GearSetFile, YamlSyntaxErrorGivesLineAndColumn) {
  const std::string e = error_for("name: t\ngears: [unclosed\n");
  EXPECT_NE(e.find("YAML syntax error"), std::string::npos) << e;
}

TEST(GearSetFile, MissingFileIsNamed) {
  try {
    load_gearset("/nonexistent/spec.yaml");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/spec.yaml: cannot open"), std::string::npos);
  }
}

// A helical gear is given by its normal values, helix angle and hand, and read as its transverse
// section (geometry/helical.hpp); a thinning along the flank normal becomes the section's
// thinning along its own normal, /cos β_b. Normal values on a spur gear, a transverse module on a
// helical one, or a helix without its hand are refused, each naming the key.
TEST(GearSetFile, AHelicalGearIsReadFromItsNormalValues) {
  const std::string dir = std::filesystem::temp_directory_path() / "gearsim_spec_helical.yaml";
  {
    std::ofstream(dir)
        << "name: t\ndensity_kg_m3: 7850\ngears:\n"
           "  pinion: {kind: external, teeth: 20, normal_module_m: 0.002, normal_pressure_angle_deg: 20, helix_angle_deg: 15,"
           " hand: right, face_width_m: 0.02, thinning_per_flank_m: 1.0e-5}\n"
           "  wheel: {kind: external, teeth: 40, normal_module_m: 0.002, helix_angle_deg: 15, hand: left, face_width_m: 0.02}\n"
           "train: {type: pair, driver: pinion, driven: wheel}\n";
  }
  const GearSetFile f = load_gearset(dir);
  std::filesystem::remove(dir);
  const GearSpec &p = f.gear("pinion"), &w = f.gear("wheel");
  const double beta = 15 * std::numbers::pi / 180;
  EXPECT_NEAR(p.helix_angle_rad, beta, 1e-15);
  EXPECT_NEAR(w.helix_angle_rad, -beta, 1e-15);  // left hand
  EXPECT_NEAR(p.module_m, 0.002 / std::cos(beta), 1e-18);
  EXPECT_NEAR(std::tan(w.pressure_angle_rad), std::tan(20 * std::numbers::pi / 180) / std::cos(beta), 1e-15);  // α_n 20° by default
  const double beta_b = std::atan(std::tan(beta) * std::cos(p.pressure_angle_rad));
  EXPECT_NEAR(p.thinning_per_flank_m, 1.0e-5 / std::cos(beta_b), 1e-18);
  const std::string g = "name: t\ndensity_kg_m3: 7850\ngears:\n  g: {kind: external, teeth: 20, face_width_m: 0.02, ";
  EXPECT_NE(
      error_for(g + "module_m: 0.002, helix_angle_deg: 15, hand: right}\n").find("module_m: a helical gear is given by its normal values"),
      std::string::npos);
  EXPECT_NE(error_for(g + "normal_module_m: 0.002, helix_angle_deg: 15}\n").find("hand"), std::string::npos);
  EXPECT_NE(error_for(g + "normal_module_m: 0.002, helix_angle_deg: 15, hand: up}\n").find("hand"), std::string::npos);
  EXPECT_NE(error_for(g + "module_m: 0.002, hand: right}\n").find("hand: only a helical gear"), std::string::npos);
  EXPECT_NE(error_for(g + "module_m: 0.002, normal_module_m: 0.002}\n").find("normal_module_m: only a helical gear"), std::string::npos);
  EXPECT_NE(error_for(g + "normal_module_m: 0.002, helix_angle_deg: 50, hand: right}\n").find("helix_angle_deg"), std::string::npos);
}

// Flank errors that take a tooth to a point are refused where the gear is written, naming the
// file, line and key like every other input error (not only when the run draws the gear).
TEST(GearSetFile, FlankErrorsThatMakeAToothPointedAreRefusedWithTheirLine) {
  const std::string e = error_for(
      "name: t\ndensity_kg_m3: 7850\ngears:\n"
      "  g: {kind: external, teeth: 20, module_m: 0.001, face_width_m: 0.01, errors: {flank_offsets: [{tooth: 0, flank: ccw, "
      "normal_offset_m: -4.0e-4}, {tooth: 0, flank: cw, normal_offset_m: -4.0e-4}]}}\n");
  EXPECT_NE(e.find(".yaml:4:"), std::string::npos) << e;
  EXPECT_NE(e.find("gears.g: gear 'g': tooth 0: flank errors make the tooth pointed"), std::string::npos) << e;
}

}  // namespace test_gearset_file
}  // namespace gearsim::input
