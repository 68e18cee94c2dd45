// The multibody engine (physics/multibody_engine.hpp, solver.engine: multibody, the default): the
// joint tree in reduced coordinates and one direct solve of the contact, bearing and motor rows.
//  - A rigid sun shares its torque between three identical planets exactly: the load each
//    carries is T_sun/(3·r_b) within 0.1 %, at the default settings (no iteration count to tune;
//    the rigid_bodies engine needed 1000 sequential-impulse iterations for this).
//  - On the paper's healthy run it agrees with the rigid_bodies engine on what both get right:
//    carrier speed, mean mesh forces, transmission error.
//  - It refuses what a tree of joints cannot hold, naming the body.
#include <gtest/gtest.h>

#include <numbers>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "core/errors.hpp"
#include "input/scenario_file.hpp"
#include "physics/world.hpp"
#include "sim/observer.hpp"
#include "sim/simulate.hpp"
#include "tests/support/asset_scenario.hpp"

namespace gearsim {
namespace test_multibody {

namespace fs = std::filesystem;
const fs::path kScenarios = fs::path(GEARSIM_SOURCE_DIR) / "assets/scenarios";

// Mean normal force of every gear pair (sum over its tooth contacts) and of the carrier speed
// over the steps after `from_s`.
struct MeanForces : sim::Observer {
  explicit MeanForces(double from) : from_s(from) {}
  double from_s;
  std::map<std::string, double> force_N;
  double carrier_speed = 0, te_min = 1e9, te_max = -1e9;
  long n = 0;
  void on_step(const physics::World& w) override {
    if (w.time_s() < from_s) return;
    std::map<std::string, double> step;
    for (const physics::ContactSample& c : w.contacts()) {
      const physics::GearPairInfo& p = w.gear_pairs()[static_cast<std::size_t>(c.pair)];
      step[p.body_a + "/" + p.body_b] += c.normal_force_N;
    }
    for (const auto& [k, v] : step) force_N[k] += v;
    for (const physics::BodyState& b : w.bodies())
      if (b.name == "carrier") carrier_speed += b.speed_rad_s;
    ++n;
  }
  double mean(const std::string& pair) const { return force_N.count(pair) ? force_N.at(pair) / static_cast<double>(n) : 0.0; }
};

TEST(Multibody, ARigidSunSharesItsTorqueEquallyBetweenThreePlanetsAtDefaultSettings) {
  // The paper's set turned slowly (9 rad/s) against 20 N·m on the carrier, the sun in a rigid
  // hinge, all three planets the healthy gear, frictionless flanks: each sun–planet mesh carries
  // T_sun/(3·r_b,sun) = (20/5)/(3·0.012·cos 20°) = 118.24 N.
  const physics::Scenario s = input::load_scenario(kScenarios / "paper_te_loaded.yaml", {"duration_s=0.4", "planetary.faulty_planets={}"});
  ASSERT_EQ(s.solver.engine, physics::SolverEngine::multibody);  // the default
  MeanForces obs(0.2);  // after the 0.1 s ramp
  const sim::RunSummary r = sim::simulate(s, {&obs});
  ASSERT_EQ(r.status, sim::RunStatus::Completed);
  const double expected = (20.0 / 5.0) / (3 * 0.012 * std::cos(20.0 * M_PI / 180.0));
  double sum = 0;
  for (int p = 0; p < 3; ++p) sum += obs.mean("sun/planet_" + std::to_string(p));
  for (int p = 0; p < 3; ++p) {
    const double f = obs.mean("sun/planet_" + std::to_string(p));
    std::printf("  sun/planet_%d: %.4f N (share %.5f %%, T/(3 r_b) = %.4f N)\n", p, f, 100 * f / sum, expected);
    EXPECT_NEAR(f, sum / 3, 1e-3 * sum / 3) << "planet " << p;
    EXPECT_NEAR(f, expected, 1e-3 * expected) << "planet " << p;
  }
}

TEST(Multibody, AgreesWithTheRigidBodyEngineOnThePaperRun) {
  // Healthy paper set, floating sun, 104.7 rad/s: 0.15 s, means over 0.07–0.15 s (after the
  // 0.05 s ramp). Both engines solve the same implicit contact springs; the rigid-body one
  // approximately (50 sequential-impulse sweeps), this one exactly.
  auto run = [](const std::string& engine) {
    const physics::Scenario s = input::load_scenario(kScenarios / "paper_dynamics_healthy.yaml",
                                                     {"duration_s=0.15", "output.per_step_log=false", "solver.engine=" + engine});
    MeanForces obs(0.07);
    const sim::RunSummary r = sim::simulate(s, {&obs});
    EXPECT_EQ(r.status, sim::RunStatus::Completed) << engine;
    return obs;
  };
  const MeanForces mb = run("multibody"), rb = run("rigid_bodies");
  const double wc_mb = mb.carrier_speed / static_cast<double>(mb.n), wc_rb = rb.carrier_speed / static_cast<double>(rb.n);
  std::printf("  carrier %.6f vs %.6f rad/s\n", wc_mb, wc_rb);
  EXPECT_NEAR(wc_mb, 104.7 / 5, 1e-4 * 104.7 / 5);  // the ideal ratio 5
  EXPECT_NEAR(wc_mb, wc_rb, 1e-4 * wc_rb);
  for (const auto& [pair, total] : rb.force_N) {
    const double a = mb.mean(pair), b = rb.mean(pair);
    std::printf("  %-16s %.4f vs %.4f N\n", pair.c_str(), a, b);
    EXPECT_NEAR(a, b, 1e-3 * b) << pair;
  }
}

TEST(Multibody, TheActiveSetSolvesTheRowsFromTheLastStepAndAgreesWithDantzig) {
  // verify.row_solver active_set (the default) against dantzig on the healthy paper set (friction
  // 0.05, floating sun): the warm start settles nearly every step, the cold first steps may fall
  // back to Dantzig. With verify.friction_model stick_slip the mean mesh forces agree within 1e-4
  // (Dantzig's friction bounds are taken from its frictionless normals, the active set's from the
  // coupled ones: measured 2.6e-5 apart over 1 s, docs/solver.md). With sliding (the default) each
  // friction impulse is a fixed multiple of its normal's, which both solve exactly (Dantzig in
  // rounds, the fixed impulses on the right-hand side): within the solves' 1e-9.
  auto run = [](const std::string& row_solver, const std::string& friction, sim::RunSummary& r) {
    const physics::Scenario s = input::load_scenario(
        kScenarios / "paper_dynamics_healthy.yaml",
        {"duration_s=0.15", "output.per_step_log=false", "verify.row_solver=" + row_solver, "verify.friction_model=" + friction});
    MeanForces obs(0.07);
    r = sim::simulate(s, {&obs});
    EXPECT_EQ(r.status, sim::RunStatus::Completed) << row_solver << " " << friction;
    return obs;
  };
  for (const std::string friction : {"stick_slip", "sliding"}) {
    sim::RunSummary ra, rd;
    const MeanForces as = run("active_set", friction, ra), dz = run("dantzig", friction, rd);
    std::printf("  %s: active set %ld steps by it, %ld by Dantzig\n", friction.c_str(), ra.profile.active_set_solves,
                ra.profile.dantzig_solves);
    EXPECT_EQ(rd.profile.active_set_solves, 0);
    EXPECT_EQ(rd.profile.dantzig_solves, rd.steps + rd.profile.onset_splits);  // a split step is solved per piece
    EXPECT_EQ(ra.profile.active_set_solves + ra.profile.dantzig_solves, ra.steps + ra.profile.onset_splits);
    EXPECT_GT(ra.profile.active_set_solves, 0.99 * static_cast<double>(ra.steps));
    ASSERT_EQ(dz.force_N.size(), 6u);
    for (const auto& [pair, total] : dz.force_N) {
      const double a = as.mean(pair), b = dz.mean(pair);
      std::printf("  %-16s %.9f vs %.9f N\n", pair.c_str(), a, b);
      EXPECT_NEAR(a, b, (friction == "sliding" ? 1e-9 : 1e-4) * b) << pair << " " << friction;
    }
  }
}

TEST(Multibody, TheProfileCountsTheFlankVisitsThatFoundEveryContact) {
  // World::Profile::flank_visits on the healthy paper set: every contact a step keeps was solved
  // on some flank — continued from the last step, shared between the passes, searched in full
  // or tracked (a skipped, renewed or parked flank gives none) —, so their sum bounds the
  // contacts over the steps from above; and the teeth stay in mesh from step to step, so the
  // continued solves outnumber the full searches and tracked flanks (onsets, the first step's
  // search of every flank, flanks leaving their records' reach). Measured at this commit: 11.23
  // contacts a step; 12.86 continued, 1.66 shared, 1.79 searched, 0.80 tracked, 117 skipped, 4.0
  // renewed, 13.1 parked. Without the coherent search nothing is counted.
  struct ContactCount : sim::Observer {
    long contacts = 0;
    void on_step(const physics::World& w) override { contacts += static_cast<long>(w.contacts().size()); }
  };
  for (const bool coherent : {true, false}) {
    const physics::Scenario s = input::load_scenario(
        kScenarios / "paper_dynamics_healthy.yaml",
        {"duration_s=0.02", "output.per_step_log=false", std::string("verify.coherent_search=") + (coherent ? "true" : "false")});
    ContactCount count;
    const sim::RunSummary r = sim::simulate(s, {&count});
    ASSERT_EQ(r.status, sim::RunStatus::Completed);
    const auto& v = r.profile.flank_visits;
    const auto per = [&](long c) { return static_cast<double>(c) / static_cast<double>(r.steps); };
    std::printf(
        "  coherent %d: %ld steps, %.2f contacts a step; flanks a step: %.2f continued (%.2f at a tip circle), %.2f shared, %.2f searched, "
        "%.2f tracked, %.2f skipped, %.2f renewed, %.2f parked\n",
        coherent, r.steps, per(count.contacts), per(v.continued), per(v.crossings), per(v.shared), per(v.searched), per(v.tracked),
        per(v.skipped), per(v.renewed), per(v.parked));
    if (!coherent) {
      EXPECT_EQ(v.searched + v.tracked + v.skipped + v.continued + v.renewed + v.shared + v.crossings + v.parked, 0);
      continue;
    }
    ASSERT_GT(count.contacts, 0);
    EXPECT_LE(count.contacts, v.continued + v.shared + v.searched + v.tracked);
    EXPECT_LE(v.crossings, v.continued);
    // A tooth pair stays engaged for ≈ 1.6 mesh periods (5 ms, 250 steps here): all but its
    // first step continue it.
    EXPECT_GT(v.continued, 0.8 * static_cast<double>(count.contacts));
    EXPECT_GT(v.continued, v.searched + v.tracked);
  }
}

TEST(Multibody, ThePlanarMassMatrixGivesTheArticulatedBodySolvesAnswer) {
  // verify.mass_matrix planar (the default: the links' Jacobians from their joint axes, M from
  // them, Cholesky) against articulated (Bullet's Jacobian tree walks and one articulated-body
  // solve per coordinate for M⁻¹) on the healthy paper set: the same equations, so the same
  // mean mesh forces and carrier speed to the solves' rounding (the 1e-9 that active set and
  // Dantzig agree to above), on the floating sun (a planar joint: three coordinates) and on a
  // rigid one (a hinge), with the sun's bearing springs and both friction models. (With every
  // planet on a bearing on the turning carrier, paper_dynamics_bearings, the means amplify
  // rounding more — active set and Dantzig differ there by up to 7e-9 over 0.12 s —: the test
  // below compares the equations themselves.)
  struct Case {
    std::string name;
    std::vector<std::string> settings;
  };
  struct File {
    std::string scenario;
    std::vector<std::string> settings;
  };
  const std::vector<std::pair<Case, File>> cases = {
      {{"floating sun, sliding friction", {}}, {"paper_dynamics_healthy.yaml", {}}},
      {{"floating sun, stick_slip friction", {"verify.friction_model=stick_slip"}}, {"paper_dynamics_healthy.yaml", {}}},
      {{"rigid sun (paper_te_loaded)", {}}, {"paper_te_loaded.yaml", {"planetary.faulty_planets={}"}}}};
  for (const auto& [c, file] : cases) {
    const bool rigid = c.name.find("rigid") != std::string::npos;
    auto run = [&](const std::string& mass_matrix) {
      std::vector<std::string> set = {"duration_s=0.12", "output.per_step_log=false", "verify.mass_matrix=" + mass_matrix};
      set.insert(set.end(), c.settings.begin(), c.settings.end());
      set.insert(set.end(), file.settings.begin(), file.settings.end());
      const physics::Scenario s = input::load_scenario(kScenarios / file.scenario, set);
      EXPECT_EQ(s.solver.mass_matrix,
                mass_matrix == "planar" ? physics::SolverDef::MassMatrix::planar : physics::SolverDef::MassMatrix::articulated);
      MeanForces obs(rigid ? 0.1 : 0.07);
      const sim::RunSummary r = sim::simulate(s, {&obs});
      EXPECT_EQ(r.status, sim::RunStatus::Completed) << c.name << " " << mass_matrix;
      return obs;
    };
    const MeanForces pl = run("planar"), ar = run("articulated");
    ASSERT_EQ(pl.force_N.size(), 6u) << c.name;
    ASSERT_GT(pl.n, 0) << c.name;
    EXPECT_NEAR(pl.carrier_speed / static_cast<double>(pl.n), ar.carrier_speed / static_cast<double>(ar.n),
                1e-9 * std::abs(ar.carrier_speed / static_cast<double>(ar.n)))
        << c.name;
    for (const auto& [pair, total] : ar.force_N) {
      const double a = pl.mean(pair), b = ar.mean(pair);
      std::printf("  %s, %-16s %.9f vs %.9f N\n", c.name.c_str(), pair.c_str(), a, b);
      EXPECT_GT(b, 1.0) << c.name << " " << pair;  // the pairs carry load
      EXPECT_NEAR(a, b, 1e-9 * b) << c.name << " " << pair;
    }
  }
}

TEST(Multibody, ThePlanarMassMatrixLinkJacobiansAndFreeMotionAreBulletsAtEveryStep) {
  // World::set_mass_matrix_check: at every step, at the same pose, M from the links' Jacobians
  // times the articulated-body solves' M⁻¹ is the identity, each link Jacobian from the joint
  // axes is Bullet's tree walk's, and the joint accelerations of the applied forces alone
  // (M·q̈ = Q − c, PlanarMass::free_velocities) are Bullet's articulated-body pass's at the same state,
  // to rounding — on the floating sun (7 coordinates) and on paper_dynamics_bearings (18: planets
  // on bearings on the turning carrier, the carrier on bearings, the ring on springs: planar
  // joints below a rotating link, where the centripetal and Coriolis terms c act). Besides the
  // load torque on the carrier, pulses of force and torque along all three axes strike a planet
  // and the sun (link forces through the chains; their out-of-plane parts must do nothing).
  for (const std::string scenario : {"paper_dynamics_healthy.yaml", "paper_dynamics_bearings.yaml"}) {
    physics::Scenario s = input::load_scenario(kScenarios / scenario, {"output.per_step_log=false"});
    const double h = s.solver.time_step_s;
    physics::ImpulseDef planet{"planet_1", 500 * h, 1000 * h, Eigen::Vector3d(40, -25, 70), Eigen::Vector3d(0.3, -0.2, 0.8)};
    physics::ImpulseDef sun{"sun", 1200 * h, 800 * h, Eigen::Vector3d(-15, 30, -5), Eigen::Vector3d(0.1, 0.4, -0.5)};
    s.impulses = {planet, sun};
    physics::World w(s);
    w.set_mass_matrix_check(true);
    for (int i = 0; i < 3000; ++i) w.step();
    const physics::World::MassMatrixCheck& c = w.mass_matrix_check();
    std::printf(
        "  %s: %ld steps checked, max |M·M⁻¹ − I| %.2e, link Jacobians max difference %.2e, free-motion q̈ max difference %.2e of the "
        "largest\n",
        scenario.c_str(), c.steps, c.identity_residual, c.jacobian_difference, c.free_velocity_difference);
    EXPECT_GE(c.steps, 3000) << scenario;
    EXPECT_LT(c.identity_residual, 1e-13) << scenario;
    EXPECT_LT(c.jacobian_difference, 1e-14) << scenario;
    EXPECT_LT(c.free_velocity_difference, 1e-12) << scenario;
    // The planar kinematics (planar_kinematics.cpp: positions, poses, link velocities in
    // closed form) against Bullet's position step, forward kinematics and link velocities from
    // the same coordinates, at every step.
    std::printf("  %s: planar kinematics, %ld steps: coordinates %.2e, centres %.2e m, bases %.2e, link velocities %.2e\n",
                scenario.c_str(), c.kinematics_steps, c.coordinate_difference, c.centre_difference_m, c.basis_difference,
                c.link_velocity_difference);
    EXPECT_GE(c.kinematics_steps, 3000) << scenario;
    EXPECT_LT(c.coordinate_difference, 1e-18) << scenario;
    EXPECT_LT(c.centre_difference_m, 1e-15) << scenario;
    EXPECT_LT(c.basis_difference, 1e-14) << scenario;
    EXPECT_LT(c.link_velocity_difference, 1e-12) << scenario;
  }
  // Not used (and so not checked) where the articulated path is asked for.
  physics::World w(input::load_scenario(kScenarios / "paper_dynamics_healthy.yaml", {"verify.mass_matrix=articulated"}));
  w.set_mass_matrix_check(true);
  w.step();
  EXPECT_EQ(w.mass_matrix_check().steps, 0);
}

TEST(Multibody, TheDofSpaceSolveIsTheRowSpaceSolve) {
  // The rows of a planar tree are solved in its coordinates' space (PrimalSolve: K = M +
  // Σ J_f·Jᵀ/D over the spring rows, the stiff rows by their Schur complement); with
  // World::set_mass_matrix_check the folded row-space solve (n × n) runs too from the same bound
  // states, at every step: the same impulses to rounding — with sliding friction folded into the
  // normals, with stick-slip friction (sticking rows are stiff unknowns beside the motor), on
  // the bearing-mounted set (18 coordinates, bearing springs as rows), on the rigid sun, and with
  // the sun's bearing 1e6 times stiffer than the paper's, the stiffest the input takes (1e13 N/m:
  // compliance 1/(h·θ·(θ·h·k + c)) ≈ 1e-3 against a diagonal ≈ 1/m_sun ≈ 32, 3e-5 of it, below
  // kSoftSpring = 1e-4: solved as a stiff row).
  // And the velocity change the step applies, the dof-space solve's own dv, against M⁻¹·Jᵀ·λ.
  struct Case {
    std::string scenario;
    std::vector<std::string> settings;
  };
  const std::vector<Case> cases = {{"paper_dynamics_healthy.yaml", {}},
                                   {"paper_dynamics.yaml", {"verify.friction_model=stick_slip"}},
                                   {"paper_dynamics_bearings.yaml", {}},
                                   {"paper_te_loaded.yaml", {}},
                                   {"paper_dynamics_healthy.yaml", {"planetary.floating_sun.radial_stiffness_N_per_m=1e13"}}};
  for (const Case& c : cases) {
    std::vector<std::string> set = {"output.per_step_log=false"};
    set.insert(set.end(), c.settings.begin(), c.settings.end());
    physics::World w(input::load_scenario(kScenarios / c.scenario, set));
    w.set_mass_matrix_check(true);
    for (int i = 0; i < 3000; ++i) w.step();
    const physics::World::MassMatrixCheck& k = w.mass_matrix_check();
    std::printf(
        "  %s %s: %ld solves compared, max |Δλ| %.2e of the largest; %ld did not settle (%ld of them settled by the row-space solve)\n",
        c.scenario.c_str(), c.settings.empty() ? "" : c.settings[0].c_str(), k.row_solves_compared, k.row_solve_difference,
        k.row_solve_fallbacks, k.row_solve_fallbacks_settled);
    EXPECT_GE(k.row_solves_compared, 3000) << c.scenario;
    EXPECT_EQ(k.row_solve_fallbacks_settled, 0) << c.scenario;  // it settles wherever the row-space solve does
    EXPECT_LT(k.row_solve_difference, 1e-9) << c.scenario;
    EXPECT_EQ(w.failed_solves(), 0) << c.scenario;  // Dantzig solves where neither settles
    // The velocity change a step applies where the dof-space solve settled is the dv it solved
    // with, not M⁻¹·Jᵀ·λ formed again: the two agree to rounding.
    std::printf("    %ld velocity changes compared, max |Δdv| %.2e of the largest\n", k.velocity_changes_compared,
                k.velocity_change_difference);
    EXPECT_GE(k.velocity_changes_compared, 3000) << c.scenario;
    EXPECT_LT(k.velocity_change_difference, 1e-12) << c.scenario;
  }
}

TEST(Multibody, AFreeBodyIsTheRigidBodyEnginesAndFallsUnderItsLoad) {
  // A body in no joint: input/ refuses it for solver.engine multibody (ScenarioErrors); the
  // rigid-body engine carries it, and a force on it moves it as F/m says. The pulse (no gravity in
  // the world) is F(τ) = F·sin(πτ/d) with d = 2t over the run's t: x(t) = (F/m)·(2t²/π)·(1 − 2/π).
  physics::Scenario s = input::load_scenario(kScenarios / "spur_pair.yaml", {"duration_s=0.01", "solver.engine=rigid_bodies"});
  const double t = 0.01, force_N = 1, mass_kg = 1;
  physics::BodyDef free_body;
  free_body.name = "loose_weight";
  free_body.mass_kg = mass_kg;
  free_body.principal_inertia_kg_m2 = Eigen::Vector3d(1e-3, 1e-3, 1e-3);
  free_body.pose.position_m = Eigen::Vector3d(0, 0, 0.5);  // clear of the gears
  s.bodies.push_back(free_body);
  physics::ImpulseDef push;
  push.body = "loose_weight";
  push.duration_s = 2 * t;
  push.force_N = Eigen::Vector3d(0, 0, -force_N);
  s.impulses.push_back(push);
  physics::World w(s);
  while (w.time_s() < t - 1e-12) w.step();
  const physics::BodyState& b = w.bodies().back();
  ASSERT_EQ(b.name, "loose_weight");
  const double drop = 0.5 - b.position_m.z();
  const double exact = force_N / mass_kg * 2 * t * t / std::numbers::pi * (1 - 2 / std::numbers::pi);
  // Semi-implicit Euler: the force sampled at step starts, positions from end velocities; its
  // error is of order h/t (1e-3 at the scenario's step): 1 %.
  EXPECT_NEAR(drop, exact, 0.01 * exact) << "drop " << drop << " m against " << exact << " m";
  EXPECT_NEAR(b.position_m.x(), 0, 1e-12);
}

TEST(Multibody, AJointTreeListedChildFirstIsBuiltParentFirst) {
  // The planetary macro lists the planets before the carrier they turn on; the engine orders the
  // links itself, and the tree starts exactly at the bodies' poses (checked when it is built).
  const physics::Scenario s = input::load_scenario(kScenarios / "paper_dynamics_healthy.yaml", {"duration_s=0.01"});
  int carrier = -1, first_planet = -1;
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    if (s.bodies[i].name == "carrier") carrier = static_cast<int>(i);
    if (s.bodies[i].name == "planet_0") first_planet = static_cast<int>(i);
  }
  ASSERT_GE(carrier, 0);
  ASSERT_GE(first_planet, 0);
  physics::World w(s);
  for (int k = 0; k < 50; ++k) w.step();
  EXPECT_EQ(w.failed_solves(), 0);
  // Planets ride on the carrier: their centres keep the carrier's centre distance, 30 mm.
  const Eigen::Vector3d c = w.bodies()[static_cast<std::size_t>(carrier)].position_m;
  const Eigen::Vector3d p = w.bodies()[static_cast<std::size_t>(first_planet)].position_m;
  EXPECT_NEAR((p - c).head<2>().norm(), 0.030, 1e-9);
}

}  // namespace test_multibody
}  // namespace gearsim

namespace gearsim {
namespace test_multibody {

// A wheel (J = 0.02 kg·m²) on a bearing with a torsional spring k_t = 200 N·m/rad, struck at
// t = 0 by a constant torque T = 1 N·m: θ(t) = (T/k_t)(1 − cos ωt), ω = √(k_t/J) = 100 rad/s.
// The angle at t = 0.05 s (ωt = 5) against that, at steps h and h/2 (ω·h = 0.1, 0.05).
double oscillator_error(const std::string& integrator, double h) {
  const fs::path file = test::fresh_test_dir() / "oscillator.yaml";
  std::ofstream(file)
      << "name: oscillator\nduration_s: 0.05\n"
         "bodies:\n  - {name: wheel, mass_kg: 1.0, principal_inertia_kg_m2: [0.01, 0.01, 0.02]}\n"
         "joints:\n  - {name: hinge, body: wheel, bearing: {radial_stiffness_N_per_m: 1.0e7, torsional_stiffness_N_m_per_rad: 200}}\n"
         "loads:\n  - {joint: hinge, constant_torque_N_m: 1}\n"
         "output: {sample_rate_hz: 100, per_step_log: false}\n";
  const physics::Scenario s = input::load_scenario(file, {"solver.time_step_s=" + std::to_string(h), "solver.integrator=" + integrator});
  struct Angle : sim::Observer {
    double angle = 0, time = 0;
    void on_step(const physics::World& w) override {
      time = w.time_s();
      for (const physics::BodyState& b : w.bodies())
        if (b.name == "wheel") angle = b.angle_rad;
    }
  } obs;
  const sim::RunSummary r = sim::simulate(s, {&obs});
  EXPECT_EQ(r.status, sim::RunStatus::Completed);
  const double exact = (1.0 / 200) * (1 - std::cos(100 * obs.time));
  return std::abs(obs.angle - exact);
}

TEST(Multibody, BDF2IsSecondOrderAndImplicitEulerFirst) {
  // Halving the step divides the error by 2 with implicit Euler (θ = 1, the default), by 4 with
  // BDF2 (solver.integrator: bdf2); at ω·h = 0.1 already BDF2's is the smaller (measured: 8.8e-5
  // against 3.7e-4 rad, of a 1e-2 rad swing).
  const double euler = oscillator_error("theta", 1e-3), euler_half = oscillator_error("theta", 5e-4);
  const double bdf2 = oscillator_error("bdf2", 1e-3), bdf2_half = oscillator_error("bdf2", 5e-4);
  EXPECT_NEAR(euler / euler_half, 2.0, 0.3) << euler << " " << euler_half;
  EXPECT_NEAR(bdf2 / bdf2_half, 4.0, 0.6) << bdf2 << " " << bdf2_half;
  EXPECT_LT(bdf2, 0.5 * euler);
  // trapezoid_closed: no contact here, so θ = ½ every step: the trapezoidal rule, second order.
  const double trap = oscillator_error("trapezoid_closed", 1e-3), trap_half = oscillator_error("trapezoid_closed", 5e-4);
  EXPECT_NEAR(trap / trap_half, 4.0, 0.6) << trap << " " << trap_half;
}

}  // namespace test_multibody
}  // namespace gearsim
