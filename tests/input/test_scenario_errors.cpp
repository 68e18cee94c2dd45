// Scenario files: every kind of bad input is refused with a message naming the file, the key
// path and what was expected. One test per kind; each edits one line of a small valid scenario.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>

#include "input/scenario_file.hpp"
#include "core/errors.hpp"

namespace gearsim::input {
namespace test_scenario_errors {

namespace fs = std::filesystem;
const fs::path kPaperSpec = fs::path(GEARSIM_SOURCE_DIR) / "assets/specs/paper_gearset.yaml";

// A fresh folder per test for the scenario (and any spec) files it writes.
fs::path test_dir() {
  const fs::path d =
      fs::temp_directory_path() / "gearsim_scenario_errors" / ::testing::UnitTest::GetInstance()->current_test_info()->name();
  fs::create_directories(d);
  return d;
}

void write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

// The error load_scenario gives for `text` saved as bad.yaml in the test's folder ("" if none).
std::string error_for(const std::string& text) {
  const fs::path p = test_dir() / "bad.yaml";
  write(p, text);
  try {
    load_scenario(p);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// A wheel on a hinge, driven and loaded: the smallest valid scenario (no files needed).
const std::string kGood =
    "name: t\n"
    "duration_s: 0.1\n"
    "bodies:\n"
    "  - {name: wheel, mass_kg: 1.0, principal_inertia_kg_m2: [0.01, 0.01, 0.02]}\n"
    "joints:\n"
    "  - {name: hinge, body: wheel, axis: [0, 0, 1]}\n"
    "motors:\n"
    "  - {joint: hinge, target_speed_rad_s: 1, max_torque_N_m: 1}\n"
    "loads:\n"
    "  - {joint: hinge, constant_torque_N_m: -0.1}\n";

std::string edited(const std::string& from, const std::string& to) {
  std::string t = kGood;
  const std::size_t at = t.find(from);
  if (at == std::string::npos) throw std::runtime_error("test text lacks " + from);
  return t.replace(at, from.size(), to);
}

// The message names the file, its line (when the key is in the file) and the key path.
#define EXPECT_NAMES(error, ...)                                                              \
  do {                                                                                        \
    const std::string e_ = (error);                                                           \
    EXPECT_NE(e_.find("bad.yaml"), std::string::npos) << e_;                                  \
    for (const char* part : {__VA_ARGS__}) EXPECT_NE(e_.find(part), std::string::npos) << e_; \
  } while (0)

TEST(ScenarioErrors, GoodScenarioLoads) { EXPECT_EQ(error_for(kGood), ""); }

TEST(ScenarioErrors, ASampleRateThatIsNoWholeNumberOfStepsIsRefused) {
  // 2000 Hz at 4e-5 s steps is 12.5 steps per sample: samples are taken at whole steps, so the
  // rows would come at 1923 Hz (13 steps) — refused, naming both whole-step rates nearby.
  EXPECT_NAMES(error_for(kGood + "solver: {time_step_s: 4.0e-5}\noutput: {sample_rate_hz: 2000}\n"), "output.sample_rate_hz",
               "12.5 time steps", "2083.33 Hz", "1923.08 Hz");
  // Without an output section the default 2000 Hz is checked against the solver's step.
  EXPECT_NAMES(error_for(kGood + "solver: {time_step_s: 4.0e-5}\n"), "solver", "defaults to 2000 Hz");
  EXPECT_EQ(error_for(kGood + "solver: {time_step_s: 4.0e-5}\noutput: {sample_rate_hz: 2500}\n"), "");  // 10 steps
}

TEST(ScenarioErrors, UnknownKey) { EXPECT_NAMES(error_for(kGood + "colour: blue\n"), "bad.yaml:11:", "colour: unknown key"); }

TEST(ScenarioErrors, UnknownKeyInsideABody) {
  EXPECT_NAMES(error_for(edited("mass_kg: 1.0", "mass_kg: 1.0, colour: red")), "bodies[0].colour: unknown key");
}

TEST(ScenarioErrors, WrongType) {
  EXPECT_NAMES(error_for(edited("duration_s: 0.1", "duration_s: fast")), "bad.yaml:2:", "duration_s: expected a number");
}

TEST(ScenarioErrors, CoherentSearchIsTrueOrFalse) {
  EXPECT_NAMES(error_for(kGood + "verify: {coherent_search: sometimes}\n"), "bad.yaml:11:", "verify.coherent_search",
               "expected true or false");
  EXPECT_EQ(error_for(kGood + "verify: {coherent_search: false}\n"), "");
}

// A search option that is part of another (`parent`): asking for it without the parent is
// refused, not ignored; off with it, and with the parent on either way.
void expect_part_of(const std::string& key, const std::string& parent) {
  const std::string named = "verify." + key, needs = "needs " + parent + ": true";
  EXPECT_NAMES(error_for(kGood + "verify: {" + parent + ": false, " + key + ": true}\n"), "bad.yaml:11:", named.c_str(), needs.c_str());
  EXPECT_NAMES(error_for(kGood + "verify: {" + key + ": 2}\n"), named.c_str(), "expected true or false");
  EXPECT_EQ(error_for(kGood + "verify: {" + parent + ": false, " + key + ": false}\n"), "");
  EXPECT_EQ(error_for(kGood + "verify: {" + key + ": false}\n"), "");
  EXPECT_EQ(error_for(kGood + "verify: {" + parent + ": false}\n"), "");
}

TEST(ScenarioErrors, ContinuedSearchNeedsTheCoherentOne) { expect_part_of("continued_search", "coherent_search"); }

TEST(ScenarioErrors, ParkedNearPairsNeedTheContinuation) {
  // Near pairs are parked continued solutions.
  expect_part_of("park_near_pairs", "continued_search");
  // Without the coherent search the continuation is off, and so the parking.
  EXPECT_EQ(error_for(kGood + "verify: {coherent_search: false}\n"), "");
}

TEST(ScenarioErrors, TheRowSolverAndTheMassMatrixAreOneOfTwoAndTheMultibodyEnginesOnly) {
  EXPECT_NAMES(error_for(kGood + "verify: {row_solver: lemke}\n"), "bad.yaml:11:", "verify.row_solver", "active_set", "dantzig", "lemke");
  EXPECT_NAMES(error_for(kGood + "solver: {engine: rigid_bodies}\nverify: {row_solver: dantzig}\n"), "verify.row_solver",
               "only engine multibody");
  EXPECT_EQ(error_for(kGood + "verify: {row_solver: dantzig}\n"), "");
  EXPECT_NAMES(error_for(kGood + "verify: {mass_matrix: dense}\n"), "bad.yaml:11:", "verify.mass_matrix", "planar", "articulated", "dense");
  EXPECT_NAMES(error_for(kGood + "solver: {engine: rigid_bodies}\nverify: {mass_matrix: planar}\n"), "verify.mass_matrix",
               "only engine multibody");
  EXPECT_EQ(error_for(kGood + "verify: {mass_matrix: articulated}\n"), "");
}

TEST(ScenarioErrors, TheFrictionModelIsOneOfTwoAndTheMultibodyEnginesOnly) {
  EXPECT_NAMES(error_for(kGood + "verify: {friction_model: viscous}\n"), "bad.yaml:11:", "verify.friction_model", "sliding", "stick_slip",
               "viscous");
  EXPECT_NAMES(error_for(kGood + "solver: {engine: rigid_bodies}\nverify: {friction_model: sliding}\n"), "verify.friction_model",
               "only engine multibody");
  EXPECT_EQ(error_for(kGood + "verify: {friction_model: stick_slip}\n"), "");
}

TEST(ScenarioErrors, LocatingContactOnsetsIsTheMultibodyEnginesWithEqualStepIntegratorsOnly) {
  EXPECT_NAMES(error_for(kGood + "verify: {locate_contact_onset: 1}\n"), "verify.locate_contact_onset", "expected true or false");
  EXPECT_NAMES(error_for(kGood + "solver: {engine: rigid_bodies}\nverify: {locate_contact_onset: true}\n"), "verify.locate_contact_onset",
               "only engine multibody");
  EXPECT_NAMES(error_for(kGood + "solver: {integrator: bdf2}\nverify: {locate_contact_onset: true}\n"), "verify.locate_contact_onset",
               "bdf2");
  EXPECT_EQ(error_for(kGood + "solver: {integrator: bdf2}\nverify: {locate_contact_onset: false}\n"), "");
  EXPECT_EQ(error_for(kGood + "solver: {integrator: theta}\nverify: {locate_contact_onset: true}\n"), "");
}

TEST(ScenarioErrors, AVerificationSwitchInSolverOrContactIsNamedWithWhereItBelongs) {
  for (const std::string key : {"row_solver: dantzig", "mass_matrix: articulated", "locate_contact_onset: false"})
    EXPECT_NAMES(error_for(kGood + "solver: {" + key + "}\n"), "bad.yaml:11:", "verify.");
  for (const std::string key : {"friction_model: sliding", "coherent_search: false", "continued_search: false", "park_near_pairs: false"})
    EXPECT_NAMES(error_for(kGood + "contact: {" + key + "}\n"), "bad.yaml:11:", "verify.");
}

TEST(ScenarioErrors, TheMultibodyEngineRefusesAFreeBodyAndALoopOfJointsNamingThem) {
  const std::string free_body = edited("joints:", "  - {name: loose_weight, mass_kg: 1, principal_inertia_kg_m2: [1, 1, 1]}\njoints:");
  EXPECT_NAMES(error_for(free_body), "bad.yaml:5:", "bodies[1].name", "'loose_weight' has no joint", "rigid_bodies");
  EXPECT_EQ(error_for(free_body + "solver: {engine: rigid_bodies}\n"), "");
  // wheel on arm, arm on wheel: a loop.
  std::string loop =
      edited("joints:\n",
             "  - {name: arm, mass_kg: 1, principal_inertia_kg_m2: [1, 1, 1]}\njoints:\n  - {name: pivot, body: arm, parent: wheel}\n");
  const std::string hinge = "body: wheel, axis";
  loop.replace(loop.find(hinge), hinge.size(), "body: wheel, parent: arm, axis");
  EXPECT_NAMES(error_for(loop), "loop of joints");
}

TEST(ScenarioErrors, DuplicateBodyName) {
  EXPECT_NAMES(error_for(edited("joints:", "  - {name: wheel, mass_kg: 1, principal_inertia_kg_m2: [1, 1, 1]}\njoints:")), "bodies[1].name",
               "a second body named 'wheel'");
}

TEST(ScenarioErrors, DuplicateJointName) {
  EXPECT_NAMES(error_for(edited("motors:", "  - {name: hinge, body: wheel}\nmotors:")), "joints[1].name", "a second joint named 'hinge'");
}

TEST(ScenarioErrors, JointOfAMissingBody) {
  EXPECT_NAMES(error_for(edited("body: wheel", "body: wheal")), "joints[0].body", "no body named 'wheal'");
}

TEST(ScenarioErrors, MotorOfAMissingJoint) {
  EXPECT_NAMES(error_for(edited("{joint: hinge, target", "{joint: hinj, target")), "motors[0].joint", "no joint named 'hinj'");
}

TEST(ScenarioErrors, LoadOfAMissingJoint) {
  EXPECT_NAMES(error_for(edited("{joint: hinge, constant", "{joint: axle, constant")), "loads[0].joint", "no joint named 'axle'");
}

TEST(ScenarioErrors, TransmissionOfAMissingJoint) {
  EXPECT_NAMES(error_for(kGood + "transmission: {input_joint: hinge, output_joint: shaft, ratio: 2}\n"), "transmission.output_joint",
               "no joint named 'shaft'");
}

TEST(ScenarioErrors, BodyWithBothGearAndMesh) {
  const std::string e = error_for(edited("mass_kg: 1.0, principal_inertia_kg_m2: [0.01, 0.01, 0.02]",
                                         "density_kg_m3: 7850, gear: {kind: external, teeth: 20, module_m: 0.002, face_width_m: 0.01}, "
                                         "mesh: {file: wheel.stl, unit: mm}"));
  EXPECT_NAMES(e, "bodies[0]", "more than one shape");
}

TEST(ScenarioErrors, MissingMeshFileNamesTheResolvedPath) {
  const std::string e = error_for(
      edited("mass_kg: 1.0, principal_inertia_kg_m2: [0.01, 0.01, 0.02]", "density_kg_m3: 7850, mesh: {file: parts/wheel.stl, unit: mm}"));
  const std::string resolved = (test_dir() / "parts/wheel.stl").string();
  EXPECT_NAMES(e, "bodies[0].mesh.file", "mesh file not found", resolved.c_str());
}

// Found by fuzz_scenario: a file name past the system's NAME_MAX (255 bytes) made
// std::filesystem throw filesystem_error (an internal error, exit 3) instead of refusing it.
TEST(ScenarioErrors, MeshFileNameTooLongForTheSystemIsRefusedAsNotFound) {
  const std::string name = "parts/" + std::string(300, 'w') + ".stl";
  const std::string e = error_for(
      edited("mass_kg: 1.0, principal_inertia_kg_m2: [0.01, 0.01, 0.02]", "density_kg_m3: 7850, mesh: {file: " + name + ", unit: mm}"));
  EXPECT_NAMES(e, "bodies[0].mesh.file", "mesh file not found");
}

TEST(ScenarioErrors, AMeshThatIsAFifoOrADeviceIsRefusedAtItsKeyNotWaitedOn) {
  fs::create_directories(test_dir() / "parts");
  ::mkfifo((test_dir() / "parts/fifo.stl").c_str(), 0600);
  for (const std::string& file : {std::string("parts/fifo.stl"), std::string("/dev/zero")}) {
    const std::string e = error_for(
        edited("mass_kg: 1.0, principal_inertia_kg_m2: [0.01, 0.01, 0.02]", "density_kg_m3: 7850, mesh: {file: " + file + ", unit: mm}"));
    EXPECT_NAMES(e, "bad.yaml:", "bodies[0].mesh.file", "expected a mesh file (a regular file), got a");
  }
}

TEST(ScenarioErrors, AMeshAssimpCannotReadIsRefusedAtItsKey) {
  fs::create_directories(test_dir() / "parts");
  std::ofstream(test_dir() / "parts/empty_solid.stl") << "solid x\nendsolid x\n";
  const std::string e = error_for(edited("mass_kg: 1.0, principal_inertia_kg_m2: [0.01, 0.01, 0.02]",
                                         "density_kg_m3: 7850, mesh: {file: parts/empty_solid.stl, unit: mm}"));
  EXPECT_NAMES(e, "bad.yaml:", "bodies[0].mesh.file", "empty_solid.stl: cannot parse mesh");
}

TEST(ScenarioErrors, NegativeMass) {
  EXPECT_NAMES(error_for(edited("mass_kg: 1.0", "mass_kg: -1.0")), "bad.yaml:4:", "bodies[0].mass_kg",
               "expected a mass in [1e-09, 1e+06] kg, got -1");
}

TEST(ScenarioErrors, ZeroDensity) {
  const std::string e = error_for(edited("mass_kg: 1.0, principal_inertia_kg_m2: [0.01, 0.01, 0.02]",
                                         "density_kg_m3: 0, gear: {kind: external, teeth: 20, module_m: 0.002, "
                                         "face_width_m: 0.01}"));
  EXPECT_NAMES(e, "bad.yaml:4:", "bodies[0].density_kg_m3", "expected a density in [1, 100000] kg/m³, got 0");
}

TEST(ScenarioErrors, MassPropertiesAndPosesOf1e300AreRefused) {
  const std::string body = "mass_kg: 1.0, principal_inertia_kg_m2: [0.01, 0.01, 0.02]";
  EXPECT_NAMES(error_for(edited("mass_kg: 1.0", "mass_kg: 1.0e300")), "bad.yaml:4:", "bodies[0].mass_kg",
               "expected a mass in [1e-09, 1e+06] kg, got 1e+300");
  EXPECT_NAMES(error_for(edited("[0.01, 0.01, 0.02]", "[0.01, 0.01, 1.0e300]")), "bad.yaml:4:", "bodies[0].principal_inertia_kg_m2",
               "z: expected a moment of inertia in [1e-18, 1e+09] kg·m², got 1e+300");
  EXPECT_NAMES(error_for(edited(body, body + ", position_m: [1.0e300, 0, 0]")), "bad.yaml:4:", "bodies[0].position_m",
               "x: expected a coordinate in [-1000, 1000] m, got 1e+300");
  EXPECT_NAMES(error_for(edited(body, body + ", orientation_deg: [0, 1.0e300, 0]")), "bad.yaml:4:", "bodies[0].orientation_deg",
               "y: expected an angle in [-360, 360] °, got 1e+300");
  EXPECT_NAMES(error_for(edited("axis: [0, 0, 1]", "axis: [0, 0, 1], pivot_m: [0, 0, -1.0e300]")), "bad.yaml:6:", "joints[0].pivot_m",
               "z: expected a coordinate in [-1000, 1000] m");
  EXPECT_NAMES(error_for(edited("axis: [0, 0, 1]", "axis: [1.0e300, 1.0e300, 0]")), "bad.yaml:6:", "joints[0].axis",
               "expected a direction of finite length");
}

TEST(ScenarioErrors, DriveLoadContactAndSupportNumbersOf1e300AreRefused) {
  // A motor torque limit of 1e300 ran to exit 0 before; the others diverged at the first step.
  EXPECT_NAMES(error_for(edited("max_torque_N_m: 1", "max_torque_N_m: 1.0e300")), "bad.yaml:8:", "motors[0].max_torque_N_m",
               "expected a torque limit in (0, 1e+08] N·m, got 1e+300");
  EXPECT_NAMES(error_for(edited("target_speed_rad_s: 1", "target_speed_rad_s: -1.0e300")), "bad.yaml:8:", "motors[0].target_speed_rad_s",
               "expected a motor speed in [-20000, 20000] rad/s");
  EXPECT_NAMES(error_for(edited("constant_torque_N_m: -0.1", "constant_torque_N_m: -1.0e300")),
               "bad.yaml:10:", "loads[0].constant_torque_N_m", "expected a torque in [-1e+08, 1e+08] N·m");
  EXPECT_NAMES(error_for(edited("constant_torque_N_m: -0.1", "constant_torque_N_m: -0.1, viscous_N_m_s_per_rad: 1.0e300")),
               "loads[0].viscous_N_m_s_per_rad", "expected a viscous coefficient in [0, 1e+08] N·m·s/rad");
  EXPECT_NAMES(error_for(edited("axis: [0, 0, 1]", "axis: [0, 0, 1], bearing: {radial_stiffness_N_per_m: 1.0e300}")),
               "bad.yaml:6:", "joints[0].bearing.radial_stiffness_N_per_m", "expected a stiffness in (0, 1e+13] N/m");
  EXPECT_NAMES(error_for(edited("axis: [0, 0, 1]",
                                "axis: [0, 0, 1], bearing: {radial_stiffness_N_per_m: 1e8, torsional_damping_N_m_s_per_rad: 1.0e300}")),
               "joints[0].bearing.torsional_damping_N_m_s_per_rad", "expected a torsional damping in [0, 1e+10] N·m·s/rad");
  for (const auto& [line, key, what] :
       {std::tuple{"stiffness_N_per_m_per_m: 1.0e300", "contact.stiffness_N_per_m_per_m", "a contact stiffness in (0, 1e+13] N/m per m"},
        {"damping_ratio: 1.0e300", "contact.damping_ratio", "a damping ratio in [0, 10]"},
        {"friction: 1.0e300", "contact.friction", "a friction coefficient in [0, 2]"},
        {"max_flank_departure_m: 1.0e300", "contact.max_flank_departure_m", "a flank departure in (0, 0.01] m"}})
    EXPECT_NAMES(error_for(kGood + "contact: {" + line + "}\n"), "bad.yaml:11:", key, what);
  EXPECT_NAMES(error_for(kGood + "impulses: [{body: wheel, duration_s: 0.01, torque_N_m: [0, 0, 1.0e300]}]\n"),
               "bad.yaml:11:", "impulses[0].torque_N_m", "z: expected a torque in [-1e+08, 1e+08] N·m");
  EXPECT_NAMES(error_for(kGood + "output: {sample_rate_hz: 1.0e300}\n"), "output.sample_rate_hz", "expected a rate in (0, 1e+07] Hz");
}

TEST(ScenarioErrors, AnInlineGearsModuleOf1e300IsRefused) {
  const std::string e = error_for(edited("mass_kg: 1.0, principal_inertia_kg_m2: [0.01, 0.01, 0.02]",
                                         "density_kg_m3: 7850, gear: {kind: external, teeth: 20, module_m: 1.0e300, "
                                         "face_width_m: 0.01}"));
  EXPECT_NAMES(e, "bad.yaml:4:", "bodies[0].gear.module_m", "expected a module in [1e-05, 0.1] m, got 1e+300");
}

// The pair macro with `extra` added to its mapping: of CAD meshes (a 12- and an 18-tooth gear of
// module 1 mm), or of the spur pair's generated gears.
std::string pair_error(const std::string& extra, bool meshes) {
  const std::string data = std::string(GEARSIM_SOURCE_DIR) + "/tests/data/mcad/";
  const std::string spec = std::string(GEARSIM_SOURCE_DIR) + "/assets/specs/spur_pair_gearset.yaml";
  const std::string driver = meshes ? "{mesh: {file: " + data + "mcad_m1_z12_a20_f5_b005.stl, unit: mm}, density_kg_m3: 7850}"
                                    : "{gear_from: {spec: " + spec + ", gear: pinion}}";
  const std::string driven = meshes ? "{mesh: {file: " + data + "mcad_m1_z18_a20_f5_b005.stl, unit: mm}, density_kg_m3: 7850}"
                                    : "{gear_from: {spec: " + spec + ", gear: wheel}}";
  return error_for("name: t\nduration_s: 0.1\npair:\n  driver: " + driver + "\n  driven: " + driven + "\n" + extra);
}

TEST(ScenarioErrors, ACentreDistanceOfZeroOrLessIsRefusedNotDerived) {
  // involute_pair() reads a distance ≤ 0 as "derive it": unchecked, a mesh pair would run at the
  // derived distance while its record says the distance was given (centre_distance_derived: false).
  for (const bool meshes : {true, false}) {
    EXPECT_EQ(pair_error("", meshes), "");
    for (const std::string d : {"-1", "0"}) {
      const std::string e = pair_error("  centre_distance_m: " + d + "\n", meshes);
      EXPECT_NE(e.find("bad.yaml:6:"), std::string::npos) << e;
      EXPECT_NE(e.find("pair.centre_distance_m: expected a centre distance in (0, 100] m, got " + d), std::string::npos) << e;
    }
  }
}

TEST(ScenarioErrors, AnImpulseOutsideTheRunIsRefused) {
  const std::string pulse = "impulses:\n  - {body: wheel, at_s: AT, duration_s: 0.001, torque_N_m: [0, 0, 1]}\n";
  const auto with_at = [&](const std::string& at) { return kGood + std::string(pulse).replace(pulse.find("AT"), 2, at); };
  EXPECT_EQ(error_for(with_at("0.05")), "");
  EXPECT_EQ(error_for(with_at("0.099")), "");  // ends at the run's end
  // Unchecked, the run would skip a pulse at 9999 s in a 0.1 s run without a word.
  EXPECT_NAMES(
      error_for(with_at("9999")), "bad.yaml:12:", "impulses[0].at_s",
      "the pulse from 9999 s to 9999.001 s ends after the run's end at 0.1 s: expected a pulse within [0, 0.1] s (the run would skip it)");
  EXPECT_NAMES(error_for(with_at("0.0995")), "bad.yaml:12:", "impulses[0].at_s", "ends after the run's end at 0.1 s",
               "(the run would skip its end)");
  EXPECT_NAMES(error_for(with_at("-1")), "bad.yaml:12:", "impulses[0].at_s", "expected a time in [0, 10000] s, got -1");
}

TEST(ScenarioErrors, AScenarioNameThatIsNotUtf8IsRefusedNamingTheKey) {
  // Unchecked, such a name reaches scenario.json, which JSON cannot hold (a 0-byte record).
  const std::string e = error_for(edited("name: t", "name: \"gear\xe9\""));
  EXPECT_NAMES(e, "bad.yaml:1:", "name: expected UTF-8 text, got 'gear\\xE9' (invalid byte 0xE9 at byte 5)");
}

TEST(ScenarioErrors, ZeroDuration) {
  EXPECT_NAMES(error_for(edited("duration_s: 0.1", "duration_s: 0")), "duration_s", "expected a duration in (0, 10000] s, got 0");
}

TEST(ScenarioErrors, NegativeTimeStep) {
  EXPECT_NAMES(error_for(kGood + "solver: {time_step_s: -1e-5}\n"), "solver.time_step_s",
               "expected a time step in [1e-07, 0.01] s, got -1e-05");
}

TEST(ScenarioErrors, HingeAxisOfZeroLength) {
  EXPECT_NAMES(error_for(edited("axis: [0, 0, 1]", "axis: [0, 0, 0]")), "joints[0].axis", "zero length");
}

TEST(ScenarioErrors, SampleRateAboveTheStepRate) {
  EXPECT_NAMES(error_for(kGood + "solver: {time_step_s: 1.0e-3}\noutput: {sample_rate_hz: 2000}\n"), "output.sample_rate_hz",
               "above the step rate");
}

// A planetary scenario on a gear-set spec written beside it (sun, planet and ring teeth given).
// Outlines at 20 µm chordal deviation keep the mesh analysis fast (it samples every outline point).
std::string planetary_error(int sun, int planet, int ring, int planets) {
  const fs::path d = test_dir();
  write(d / "set.yaml",
        "name: s\ndensity_kg_m3: 7850\ndefaults: {module_m: 1.0e-3, face_width_m: 0.01, chordal_deviation_m: 2.0e-5}\ngears:\n"
        "  sun: {kind: external, teeth: " +
            std::to_string(sun) +
            "}\n"
            "  planet: {kind: external, teeth: " +
            std::to_string(planet) +
            "}\n"
            "  ring: {kind: internal, teeth: " +
            std::to_string(ring) + ", rim_diameter_m: 0.12}\n");
  return error_for(
      "duration_s: 0.1\nplanetary:\n  spec: set.yaml\n  sun: sun\n  planet: planet\n  ring: ring\n"
      "  planets: " +
      std::to_string(planets) + "\n  carrier: {mass_kg: 0.3, inertia_z_kg_m2: 2.0e-4}\n");
}

TEST(ScenarioErrors, RingThatCannotMeshWithThePlanets) {
  // z_r = 97 ≠ z_s + 2·z_p = 96: the planet–ring centre distance (30.5 mm) misses the sun's (30 mm).
  EXPECT_NAMES(planetary_error(24, 36, 97, 3), "bad.yaml:6:", "planetary.ring", "centre distance");
}

TEST(ScenarioErrors, PlanetsThatCannotBeAssembledEquallySpaced) {
  // 20 + 62 = 82 teeth, not divisible by 3 planets (the centre distances agree: 20.5 mm). Small
  // gears (without undercut) keep the test fast.
  EXPECT_NAMES(planetary_error(20, 21, 62, 3), "planetary.planets", "(z_s + z_r)/N = (20 + 62)/3", "not a whole number");
}

TEST(ScenarioErrors, FaultyPlanetIndexOutOfRange) {
  const std::string e = error_for("duration_s: 0.1\nplanetary:\n  spec: " + kPaperSpec.string() +
                                  "\n  faulty_planets: {3: planet_faulty}\n  carrier: {mass_kg: 0.3, inertia_z_kg_m2: 2.0e-4}\n");
  EXPECT_NAMES(e, "planetary.faulty_planets.3", "expected a planet index 0..2");
}

TEST(ScenarioErrors, RenderSectionIsCheckedKeyByKey) {
  EXPECT_EQ(error_for(kGood + "render: {camera: sun_mesh, fps: 25, slowmo: 20, from_s: 0.01, to_s: 0.05}\n"), "");
  EXPECT_NAMES(error_for(kGood + "render: {camera: sideways}\n"), "render.camera");
  EXPECT_NAMES(error_for(kGood + "render: {fps: 0}\n"), "render.fps", "1 to 240");
  EXPECT_NAMES(error_for(kGood + "render: {width_px: 641}\n"), "render.width_px", "even");
  EXPECT_NAMES(error_for(kGood + "render: {from_s: 0.2, to_s: 0.1}\n"), "render.to_s", "after from_s");
  EXPECT_NAMES(error_for(kGood + "render: {colour: red}\n"), "render.colour: unknown key");
}

}  // namespace test_scenario_errors
}  // namespace gearsim::input
