// The expanded scenario a run records in its folder (input/scenario_record.hpp): every asset
// scenario (generated gears, CAD meshes, the planetary and pair macros, stiffness tables, fe)
// reads back to the same scenario; a damaged record names its key; a mesh edited since the run is
// refused; the record and its gear-set copy, not the original files, are what a run folder reads.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/errors.hpp"
#include "input/gearset_file.hpp"
#include "input/scenario_file.hpp"
#include "input/scenario_record.hpp"
#include "tests/support/asset_scenario.hpp"

namespace gearsim::input {
namespace test_scenario_record {

namespace fs = std::filesystem;

fs::path asset(const std::string& name) { return fs::path(GEARSIM_SOURCE_DIR) / "assets/scenarios" / name; }

std::string error_of(const nlohmann::json& j) {
  try {
    scenario_from_json(j, "rec.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ScenarioRecord, EveryAssetScenarioReadsBackToTheSameScenario) {
  for (const char* name :
       {"paper_dynamics.yaml", "paper_dynamics_healthy.yaml", "paper_te_loaded.yaml", "paper_te_rigid.yaml", "spur_pair.yaml"}) {
    const physics::Scenario s = load_scenario(asset(name));
    const nlohmann::ordered_json j = scenario_json(s);
    const physics::Scenario back = scenario_from_json(nlohmann::json::parse(j.dump()), "rec.json");
    EXPECT_EQ(scenario_json(back).dump(), j.dump()) << name;
    // Fields the comparison would miss if the writer forgot them: spot checks on the struct.
    ASSERT_EQ(back.bodies.size(), s.bodies.size()) << name;
    for (std::size_t b = 0; b < s.bodies.size(); ++b) {
      EXPECT_EQ(back.bodies[b].pose.orientation.coeffs(), s.bodies[b].pose.orientation.coeffs()) << name;
      EXPECT_EQ(back.bodies[b].mesh.has_value(), s.bodies[b].mesh.has_value()) << name;
      if (s.bodies[b].mesh) {
        EXPECT_EQ(back.bodies[b].mesh->recognised.has_value(), s.bodies[b].mesh->recognised.has_value());
      }
    }
    EXPECT_EQ(back.planetary.has_value(), s.planetary.has_value()) << name;
    EXPECT_EQ(back.fe.has_value(), s.fe.has_value()) << name;
    EXPECT_EQ(back.pair_tables.size(), s.pair_tables.size()) << name;
    EXPECT_EQ(back.contact.stiffness_tables.size(), s.contact.stiffness_tables.size()) << name;
  }
}

TEST(ScenarioRecord, TheContactSearchReadsBack) {
  // verify.coherent_search: the default (true) and false read back; a record written before the
  // key existed ran the stateless search.
  physics::Scenario s = load_scenario(asset("paper_dynamics_healthy.yaml"));
  EXPECT_TRUE(s.contact.coherent_search);
  EXPECT_TRUE(scenario_from_json(nlohmann::json::parse(scenario_json(s).dump()), "rec.json").contact.coherent_search);
  s.contact.coherent_search = false;
  nlohmann::json j = nlohmann::json::parse(scenario_json(s).dump());
  EXPECT_FALSE(scenario_from_json(j, "rec.json").contact.coherent_search);
  j["verify"].erase("coherent_search");
  EXPECT_FALSE(scenario_from_json(j, "rec.json").contact.coherent_search);
  j["verify"]["coherent_search"] = "yes";
  EXPECT_NE(error_of(j).find("verify.coherent_search"), std::string::npos) << error_of(j);
}

TEST(ScenarioRecord, TheIntegratorReadsBack) {
  // solver.integrator: trapezoid_closed (the default), theta and bdf2 read back; `theta` given
  // alone chooses the θ-method; a record without an integrator ran the θ-method.
  physics::Scenario s = load_scenario(asset("paper_dynamics_healthy.yaml"));
  EXPECT_EQ(s.solver.integrator, physics::SolverDef::Integrator::trapezoid_closed);
  EXPECT_EQ(load_scenario(asset("paper_dynamics_healthy.yaml"), {"solver.theta=0.6"}).solver.integrator,
            physics::SolverDef::Integrator::theta);
  // The rigid-body engine integrates by implicit Euler, and its scenario says so.
  const physics::Scenario rigid = load_scenario(asset("paper_dynamics_healthy.yaml"), {"solver.engine=rigid_bodies"});
  EXPECT_EQ(rigid.solver.integrator, physics::SolverDef::Integrator::theta);
  EXPECT_EQ(rigid.solver.theta, 1.0);
  EXPECT_EQ(scenario_from_json(nlohmann::json::parse(scenario_json(s).dump()), "rec.json").solver.integrator,
            physics::SolverDef::Integrator::trapezoid_closed);
  s.solver.integrator = physics::SolverDef::Integrator::bdf2;
  nlohmann::json j = nlohmann::json::parse(scenario_json(s).dump());
  EXPECT_EQ(scenario_from_json(j, "rec.json").solver.integrator, physics::SolverDef::Integrator::bdf2);
  j["solver"]["integrator"] = "trapezoid_closed";
  EXPECT_EQ(scenario_from_json(j, "rec.json").solver.integrator, physics::SolverDef::Integrator::trapezoid_closed);
  j["solver"].erase("integrator");
  EXPECT_EQ(scenario_from_json(j, "rec.json").solver.integrator, physics::SolverDef::Integrator::theta);
  j["solver"]["integrator"] = "euler";
  EXPECT_NE(error_of(j).find("solver.integrator"), std::string::npos) << error_of(j);
}

// A choice key of the record (section.key): the paper scenario's value `dflt` reads back, so
// does `other`; a record written before the key existed reads as `legacy`; an unknown name is
// refused naming the key. `of`: the key's value in a scenario.
template <typename Value, typename Of>
void expect_choice_reads_back(const std::string& section, const std::string& key, Of of, Value dflt, const std::string& other_name,
                              Value other, Value legacy, const std::string& bad) {
  physics::Scenario s = load_scenario(asset("paper_dynamics_healthy.yaml"));
  EXPECT_EQ(of(s), dflt) << key;
  nlohmann::json j = nlohmann::json::parse(scenario_json(s).dump());
  EXPECT_EQ(of(scenario_from_json(j, "rec.json")), dflt) << key;
  j[section][key] = other_name;
  EXPECT_EQ(of(scenario_from_json(j, "rec.json")), other) << key;
  j[section].erase(key);
  EXPECT_EQ(of(scenario_from_json(j, "rec.json")), legacy) << key;
  j[section][key] = bad;
  EXPECT_NE(error_of(j).find(section + "." + key), std::string::npos) << error_of(j);
}

TEST(ScenarioRecord, TheMassMatrixReadsBack) {
  // verify.mass_matrix: planar (the default) and articulated read back; a record without it ran
  // the articulated-body solves.
  using M = physics::SolverDef::MassMatrix;
  expect_choice_reads_back(
      "verify", "mass_matrix", [](const physics::Scenario& s) { return s.solver.mass_matrix; }, M::planar, "articulated", M::articulated,
      M::articulated, "dense");
}

TEST(ScenarioRecord, TheRowSolverReadsBack) {
  // verify.row_solver: active_set (the default) and dantzig read back; a record without it ran Dantzig.
  using R = physics::SolverDef::RowSolver;
  expect_choice_reads_back(
      "verify", "row_solver", [](const physics::Scenario& s) { return s.solver.row_solver; }, R::active_set, "dantzig", R::dantzig,
      R::dantzig, "lemke");
}

TEST(ScenarioRecord, TheFrictionModelReadsBack) {
  // verify.friction_model: sliding (the multibody default) and stick_slip read back; a record
  // written before the key existed ran the stick–slip rows; rigid_bodies records stick_slip
  // (Bullet's friction box).
  using F = physics::ContactDef::FrictionModel;
  expect_choice_reads_back(
      "verify", "friction_model", [](const physics::Scenario& s) { return s.contact.friction_model; }, F::sliding, "stick_slip",
      F::stick_slip, F::stick_slip, "viscous");
  EXPECT_EQ(scenario_json(load_scenario(asset("paper_dynamics_healthy.yaml")))["verify"]["friction_model"], "sliding");
  const physics::Scenario rigid = load_scenario(asset("paper_dynamics_healthy.yaml"), {"solver.engine=rigid_bodies"});
  EXPECT_EQ(rigid.contact.friction_model, F::stick_slip);
}

TEST(ScenarioRecord, LocatingContactOnsetsReadsBack) {
  // verify.locate_contact_onset: true by default for multibody with trapezoid_closed or theta,
  // recorded false where the run cannot split a step (rigid_bodies, bdf2); a record written
  // before the key existed ran without it.
  physics::Scenario s = load_scenario(asset("paper_dynamics_healthy.yaml"));
  EXPECT_TRUE(s.solver.locate_contact_onset);
  nlohmann::json j = nlohmann::json::parse(scenario_json(s).dump());
  EXPECT_EQ(j["verify"]["locate_contact_onset"], true);
  EXPECT_TRUE(scenario_from_json(j, "rec.json").solver.locate_contact_onset);
  j["verify"].erase("locate_contact_onset");
  EXPECT_FALSE(scenario_from_json(j, "rec.json").solver.locate_contact_onset);
  j["verify"]["locate_contact_onset"] = "yes";
  EXPECT_NE(error_of(j).find("verify.locate_contact_onset"), std::string::npos) << error_of(j);
  EXPECT_FALSE(load_scenario(asset("paper_dynamics_healthy.yaml"), {"solver.engine=rigid_bodies"}).solver.locate_contact_onset);
  EXPECT_FALSE(load_scenario(asset("paper_dynamics_healthy.yaml"), {"solver.integrator=bdf2"}).solver.locate_contact_onset);
}

TEST(ScenarioRecord, ARecordWithTheVerificationSwitchesInSolverAndContactReadsAsItRan) {
  // Records written before the verify object carry its keys in solver and contact: each is read
  // from there, with the same values as from a verify object.
  physics::Scenario s = load_scenario(asset("paper_dynamics_healthy.yaml"));
  s.solver.row_solver = physics::SolverDef::RowSolver::dantzig;
  s.solver.mass_matrix = physics::SolverDef::MassMatrix::articulated;
  s.contact.friction_model = physics::ContactDef::FrictionModel::stick_slip;
  s.contact.park_near_pairs = false;
  nlohmann::json j = nlohmann::json::parse(scenario_json(s).dump());
  for (const char* key : {"row_solver", "mass_matrix", "locate_contact_onset"}) j["solver"][key] = j["verify"][key];
  for (const char* key : {"friction_model", "coherent_search", "continued_search", "park_near_pairs"}) j["contact"][key] = j["verify"][key];
  j.erase("verify");
  const physics::Scenario back = scenario_from_json(j, "rec.json");
  EXPECT_EQ(back.solver.row_solver, physics::SolverDef::RowSolver::dantzig);
  EXPECT_EQ(back.solver.mass_matrix, physics::SolverDef::MassMatrix::articulated);
  EXPECT_TRUE(back.solver.locate_contact_onset);
  EXPECT_EQ(back.contact.friction_model, physics::ContactDef::FrictionModel::stick_slip);
  EXPECT_TRUE(back.contact.coherent_search);
  EXPECT_TRUE(back.contact.continued_search);
  EXPECT_FALSE(back.contact.park_near_pairs);
}

TEST(ScenarioRecord, TheContinuationReadsBack) {
  // verify.continued_search: on by default, off without the coherent search; a record written
  // before the key existed ran without it.
  physics::Scenario s = load_scenario(asset("paper_dynamics_healthy.yaml"));
  EXPECT_TRUE(s.contact.continued_search);
  nlohmann::json j = nlohmann::json::parse(scenario_json(s).dump());
  EXPECT_TRUE(scenario_from_json(j, "rec.json").contact.continued_search);
  j["verify"]["continued_search"] = false;
  EXPECT_FALSE(scenario_from_json(j, "rec.json").contact.continued_search);
  j["verify"].erase("continued_search");
  EXPECT_FALSE(scenario_from_json(j, "rec.json").contact.continued_search);
}

TEST(ScenarioRecord, ADamagedRecordNamesTheKey) {
  const nlohmann::json good = nlohmann::json::parse(scenario_json(load_scenario(asset("paper_dynamics.yaml"))).dump());
  nlohmann::json j = good;
  j["bodies"][1]["gear"]["teeth"] = "many";
  EXPECT_NE(error_of(j).find("rec.json: key bodies[1].gear.teeth: expected a finite number"), std::string::npos) << error_of(j);
  j = good;
  j["solver"].erase("time_step_s");
  EXPECT_NE(error_of(j).find("key solver.time_step_s: missing"), std::string::npos) << error_of(j);
  j = good;
  j["solver"]["time_step_s"] = 1.0;
  EXPECT_NE(error_of(j).find("key solver.time_step_s:"), std::string::npos) << error_of(j);
  j = good;
  j["bodies"][0]["orientation_wxyz"] = {2, 0, 0, 0};
  EXPECT_NE(error_of(j).find("bodies[0].orientation_wxyz: expected a unit quaternion"), std::string::npos) << error_of(j);
}

TEST(ScenarioRecord, ARecordsGearAndBodyNumbersAreCheckedAgainstTheReadersLimits) {
  const nlohmann::json good = nlohmann::json::parse(scenario_json(load_scenario(asset("paper_dynamics.yaml"))).dump());
  nlohmann::json j = good;
  j["bodies"][1]["gear"]["module_m"] = 1e300;
  EXPECT_NE(error_of(j).find("rec.json: key bodies[1].gear.module_m: expected a module in [1e-05, 0.1] m, got 1e+300"), std::string::npos)
      << error_of(j);
  j = good;
  j["bodies"][1]["gear"]["face_width_m"] = 1e300;
  EXPECT_NE(error_of(j).find("key bodies[1].gear.face_width_m: expected a face width"), std::string::npos) << error_of(j);
  j = good;
  j["bodies"][0]["position_m"] = {0, 1e300, 0};
  EXPECT_NE(error_of(j).find("key bodies[0].position_m: y: expected a coordinate in [-1000, 1000] m"), std::string::npos) << error_of(j);
}

TEST(ScenarioRecord, ARecordsDrivesContactAndSupportsAreCheckedAgainstTheReadersLimits) {
  const nlohmann::json good = nlohmann::json::parse(scenario_json(load_scenario(asset("paper_dynamics.yaml"))).dump());
  const auto error_with = [&](const nlohmann::json::json_pointer& at, double value) {
    nlohmann::json j = good;
    j[at] = value;
    return error_of(j);
  };
  using P = nlohmann::json::json_pointer;
  EXPECT_NE(error_with(P("/motors/0/max_torque_N_m"), 1e300).find("key motors[0].max_torque_N_m: expected a torque limit"),
            std::string::npos)
      << error_with(P("/motors/0/max_torque_N_m"), 1e300);
  EXPECT_NE(error_with(P("/loads/0/constant_torque_N_m"), -1e300).find("key loads[0].constant_torque_N_m: expected a torque"),
            std::string::npos);
  EXPECT_NE(error_with(P("/contact/friction"), 1e300).find("key contact.friction: expected a friction coefficient in [0, 2]"),
            std::string::npos);
  EXPECT_NE(
      error_with(P("/contact/stiffness_N_per_m_per_m"), 1e300).find("key contact.stiffness_N_per_m_per_m: expected a contact stiffness"),
      std::string::npos);
  EXPECT_NE(error_with(P("/transmission/ratio"), 1e300).find("key transmission.ratio: expected a ratio's magnitude"), std::string::npos)
      << error_with(P("/transmission/ratio"), 1e300);
}

TEST(ScenarioRecord, TheRunFoldersGearSetCopyIsCheckedAsTheOriginal) {
  const fs::path dir = test::fresh_test_dir();
  write_scenario_record(load_scenario(asset("paper_dynamics.yaml")), dir);
  std::ifstream in(dir / "gearset.yaml");
  std::string text(std::istreambuf_iterator<char>(in), {});
  const std::size_t at = text.find("module_m: 1.0e-3");
  ASSERT_NE(at, std::string::npos);
  std::ofstream(dir / "gearset.yaml") << text.replace(at, 16, "module_m: 1.0e300");
  try {
    load_gearset(read_scenario_record(dir).gearset_spec);  // as report does
    ADD_FAILURE() << "a module of 1e300 m was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("gearset.yaml:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("defaults.module_m: expected a module in [1e-05, 0.1] m, got 1e+300"), std::string::npos)
        << e.what();
  }
}

TEST(ScenarioRecord, AMeshEditedSinceTheRunIsRefused) {
  const fs::path dir = test::fresh_test_dir();
  for (const char* f : {"pinion.stl", "wheel.stl"}) fs::copy_file(fs::path(GEARSIM_SOURCE_DIR) / "assets/gears/spur_pair" / f, dir / f);
  std::string text;
  {
    std::ifstream in(asset("spur_pair.yaml"));
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  for (std::size_t at; (at = text.find("../gears/spur_pair/")) != std::string::npos;) text.replace(at, 19, "");
  std::ofstream(dir / "scenario.yaml") << text;
  const physics::Scenario s = load_scenario(dir / "scenario.yaml");
  const nlohmann::json j = nlohmann::json::parse(scenario_json(s).dump());
  EXPECT_NO_THROW(scenario_from_json(j, "rec.json"));
  std::ofstream(dir / "wheel.stl", std::ios::app) << " ";  // one byte more
  EXPECT_NE(error_of(j).find("wheel.stl changed since the run"), std::string::npos) << error_of(j);
  fs::remove(dir / "pinion.stl");
  EXPECT_NE(error_of(j).find("pinion.stl no longer exists"), std::string::npos) << error_of(j);
}

TEST(ScenarioRecord, TheRunFolderKeepsItsOwnGearSetCopy) {
  const fs::path dir = test::fresh_test_dir();
  const physics::Scenario s = load_scenario(asset("paper_dynamics.yaml"));
  ASSERT_FALSE(s.gearset_spec.empty());
  write_scenario_record(s, dir);
  const physics::Scenario back = read_scenario_record(dir);
  EXPECT_EQ(back.gearset_spec, dir / "gearset.yaml");
  std::ifstream a(s.gearset_spec), b(dir / "gearset.yaml");
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(a), {}), std::string(std::istreambuf_iterator<char>(b), {}));
  EXPECT_EQ(back.bodies.size(), s.bodies.size());
}

}  // namespace test_scenario_record
}  // namespace gearsim::input
