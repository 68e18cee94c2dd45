// Determinism: the same scenario and build give the same logs, byte for byte, run after run,
// and the logs of a short paper run match a committed hash (a golden regression: any change
// of the physics, the contact or the log format shows up here, and the new hash must be
// committed together with the reason).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace test_run_determinism {

namespace fs = std::filesystem;

// FNV-1a, 64 bit, over the files' bytes in order.
std::uint64_t hash_files(const fs::path& dir) {
  std::uint64_t h = 1469598103934665603ull;
  for (const char* name : {"state.csv", "contacts.csv", "steps.h5"}) {
    std::ifstream f(dir / name, std::ios::binary);
    EXPECT_TRUE(f.good()) << (dir / name);
    for (std::istreambuf_iterator<char> it(f), end; it != end; ++it) {
      h ^= static_cast<unsigned char>(*it);
      h *= 1099511628211ull;
    }
  }
  return h;
}

fs::path run_paper(const std::string& tag, const std::string& extra = "") {
  const fs::path dir = fs::temp_directory_path() / ("gearsim_determinism_" + tag);
  fs::remove_all(dir);
  const std::string cmd = std::string(GEARSIM_BINARY_DIR) + "/bin/gearsim run " + GEARSIM_SOURCE_DIR +
                          "/assets/scenarios/paper_dynamics_healthy.yaml --out " + dir.string() +
                          " --duration 0.004 --no-analyze" + extra + " > /dev/null 2>&1";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  return dir;
}

// The hash of the 0.004 s paper run (200 steps) on Debian 12 / x86-64 with this build. Update
// it (the failure message prints the new value) only together with the change that explains it.
// Last change: a flank table's cubic between two outline vertices takes its four knots on one
// side of an involute–fillet junction where the centred four straddle it (contact/flank_knots.cpp,
// stencil(); docs/tooth-contact.md, "The cubic beside a fillet"): the tables' tangents near the
// form circles no longer kink by 5.8e-3–1.3e-2 rad. Every hash changed (the tables' geometry);
// the coherent and stateless searches still give identical logs. On a 0.3 s faulty paper run
// against the former build: filtered mesh forces moved by at most 0.145 N (of up to 414 N),
// point samples by 2.0 N, depths by 0.027 µm, the tooth-pair counts identical; the healthy 1 s
// run's mesh-harmonic amplitudes by −0.1 to +0.3 % (sun–planet) and −0.5 to −1.4 % (planet–ring),
// its TE peak-to-peak 4.885e-5 → 4.918e-5 rad (docs/solver.md, "Where it stands (stop 42)").
// Before: FlankTable::direction()'s sine and cosine polynomials evaluated by Estrin's scheme
// instead of one Horner chain (contact/flank_table.cpp; the latency of every flank evaluation),
// and the rows' rates J·v as plain sums in coordinate order instead of Eigen's products (physics/
// world_impl.hpp, row_dot): the same to rounding — bench_contact_sweep over the paper's six meshes,
// stateless and continued: depths within 2.5e-17 m, points 2.8e-12 m, the same searches and
// counts; on a 0.3 s faulty paper run the filtered forces moved by at most 2.8e-6 N (of ≈ 119 N),
// the angles by 6.6e-12 rad. Every hash changed (the rigid bodies' and sampled ones too: the flank
// geometry is everyone's).
// Before: with the planar mass matrix the positions, the links' poses and velocities and the
// joints' angles come from the joint coordinates in closed form (physics/world_planar_kinematics.cpp:
// one sine and cosine per link) instead of Bullet's position step, forward kinematics and link
// velocities and atan2 of the bodies' transforms: the same to 2.7e-23 (coordinates), 3.6e-17 m
// (centres), 7.0e-16 (bases), 4.7e-16 (link velocities) at every step
// (Multibody.ThePlanarMassMatrixLinkJacobiansAndFreeMotionAreBulletsAtEveryStep), other rounding.
// The planar runs' hashes changed (the default's, θ = 1's, the sampled multibody one); the
// articulated and rigid-body ones did not. On a 0.3 s faulty paper run the filtered forces moved
// by at most 7.3e-6 N (of ≈ 119 N), the angles by 2.6e-10 rad, the speeds at the 2 kHz samples by
// 3.6e-10 rad/s (1.9e-6 rad/s at most, in the contact ringing).
// Before: where the dof-space solve settled the rows, the step applies the velocity change
// it solved them with instead of forming M⁻¹·Jᵀ·λ again (physics/world_planar_mass.cpp,
// velocity_change_of_x): the same to 2.4e-13 of the largest at every step
// (Multibody.TheDofSpaceSolveIsTheRowSpaceSolve), other rounding. Only the default's hash changed
// (the others solve by Dantzig, the articulated path or Bullet's rigid bodies).
// Before: the continued search's second probing pass takes a flank's interior maximum
// from the first pass where that pass solved the same two flanks' common normal in the same
// call (contact/coherent_contact.cpp, Counts::shared), instead of solving it again from the
// other side and keeping the deeper of two equal depths: over the 974 618 contacts of the paper
// sweep (bench_contact_sweep --coherent --continued --compare) depths within 2.6e-15 m, points
// 1.3e-9 m, normals 8.9e-8 rad. Every hash of a continued search changed (all four below); the
// sampled searches' did not.
// Before: with the planar mass matrix the rows are solved in the coordinates' space
// (physics/world_primal_solve.cpp: K = M + Σ J_f·Jᵀ/D over the spring rows, the stiff rows by
// their Schur complement) instead of the n × n folded rows, and M⁻¹·Jᵀ·λ comes from the Cholesky
// factor and Jᵀ·λ: the same impulses within 7.4e-14 of the largest at every step
// (Multibody.TheDofSpaceSolveIsTheRowSpaceSolve), other rounding. The planar runs' hashes
// changed (the default's, θ = 1's with Dantzig — its held friction rows' unused compliance is now
// 0 — and the sampled multibody one); the articulated and rigid-body ones did not.
// Before: with the planar mass matrix the velocities after the applied forces alone come
// from it (M·q̈ = Q − c, physics/world_planar_mass.cpp planar_free_velocities) instead of
// Bullet's articulated-body pass: the same accelerations to 1.5e-15 of the largest at every
// step (Multibody.ThePlanarMassMatrixLinkJacobiansAndFreeMotionAreBulletsAtEveryStep), other
// rounding. The hashes of the runs with the planar mass matrix changed (the default's, θ = 1's,
// the stateless/coherent sampled multibody one); the articulated and rigid-body ones did not;
// the paper runs' figures are the same to their printed digits (docs/solver.md).
// Before: with the planar mass matrix the active set solves the folded rows (a friction row
// held at a multiple of its normal's impulse folded into the normal's column, physics/
// world_planar_mass.cpp solve_rows_folded): the same solution, other rounding. Only the
// default's hash changed (the others solve by Dantzig or with the articulated path); the mean
// mesh forces still agree with the articulated path within 1e-9 (test_multibody.cpp).
// Before: solver.mass_matrix planar is the multibody engine's default on a tree whose
// joints all turn about z: the links' Jacobians from their joint axes and M⁻¹·Jᵀ through the
// Cholesky factor of M = Σ m·JᵀJ + I_zz·J_ωᵀJ_ω, where Bullet's tree walks and one articulated-
// body solve per coordinate gave them (physics/world_multibody.cpp, docs/solver.md "The planar
// mass matrix"). The three multibody hashes changed (rounding: over 0.12 s the mean mesh forces
// and carrier speed agree within 1e-9, Multibody.ThePlanarMassMatrixGivesTheArticulatedBodySolvesAnswer);
// with --set solver.mass_matrix=articulated the logs are the bytes they were (the former hashes,
// kept below); the rigid bodies' hash did not change.
// Before: Newton's method on the smooth flanks ends from the expansions only where the
// step after the last, predicted on them, is below its 1e-13 m tolerance (and within one cubic
// of each flank); continued contacts on smooth flanks start from the parabola through their
// last three solutions and may end so from steps up to 0.1 µm (contact/flank_newton_impl.hpp).
// Every hash changed: the stateless search's contacts moved by at most 1.4e-17 m in depth and
// 1.3e-10 m in point over the 974 618 of the paper sweep (bench_contact_sweep --compare).
// Before: contact.friction_model sliding is the multibody engine's default: friction is
// μ·λ_n against the slip, shared at the slip's reversal within the step, where the box ±μ·λ_n
// gave the whole reversal step the end slip's direction (physics/world_multibody.cpp,
// docs/solver.md "Friction at the pitch point"). The three multibody hashes changed, the rigid
// bodies' not (Bullet's friction); coherent and stateless searches still give identical logs.
// Before: a motor's row (or Bullet's hinge motor, rigid bodies) asks for the target speed at
// the step's end, where it asked for the one at its start: every driven body ran one step behind
// its ramp (physics/world_impl.hpp, motor_target_rad_s). Every hash changed; on 0.6 s paper runs
// the sun's angle at 0.1355 s now agrees between dt 2e-5 and 5e-6 s within 3.4e-6 rad (it lagged
// by ω·dt: 1.57e-3 rad apart), the analysed spectra unchanged (docs/solver.md).
// Before: trapezoid_closed takes θ = ½ on every step without a new contact; the θ = 1 it
// took where a persisting contact "may open" had the contact's rate with its sign inverted
// (physics/world_integrator.cpp, docs/solver.md "θ that follows the contacts"). Only the
// default's hash changed (the others run with the θ-method or rigid bodies).
// Before: Newton's method on the flanks (contact/flank_newton_impl.hpp) stops at a step
// shorter than 1 nm and takes the point it leads to from the flanks' second-order expansions
// (kNewtonTaylor_m) instead of evaluating them once more: the same contact to ~1e-15 m, not bit
// for bit. Every hash changed (the sampled search uses Newton too); on 0.3 s faulty paper runs
// the forces moved by at most 4e-4 N (of 130 N) and the depths by 6e-12 m, the trajectories'
// rounding drift (docs/tooth-contact.md, "Newton refinement on smooth flanks").
// Before: solver.row_solver active_set is the default (physics/row_lcp.hpp): the rows are
// solved from last step's bound states, exact in the friction coupling, where Dantzig fixed each
// friction bound from its normal's impulse when it reached the row (docs/solver.md, "The row
// solve"); the hashes below other than the default's run with --set solver.row_solver=dantzig.
// Before: state.csv's te_rad is anti-aliased like the forces (te_point_rad, new, holds the
// point sample): every hash below changed with it, nothing else — checked on 0.3 s runs of each
// variant: contacts.csv and steps.h5 byte-identical, state.csv's other columns identical and
// te_point_rad equal to the former te_rad (docs/decimation.md).
// Before: solver.integrator trapezoid_closed became the default (docs/solver.md, "θ that follows
// the contacts"): θ = ½ where every contact persists, 1 where one may open, and where one is new
// ½ plus the damping that removes the energy its late detection added. The θ-method's (θ = 1,
// --set solver.integrator=theta) hash is kept below. Before that: contact.continued_search (default
// true) solves a flank's contact by Newton's method from last step's solution (docs/tooth-contact.md,
// "Continuation"): depths agree with the sampled search's within 0.1 nm, but not bit for bit (the
// sampled search's hashes are kept below).
// Before: a gear's planar pose takes its rotation's cosine and sine from its frame's x axis,
// normalised in the plane, instead of libm's sincos of the angle atan2 gave (the same rotation
// to rounding): every hash changed; on a 0.3 s faulty paper run the forces moved by at most
// 2.9e-6 N (of ≈ 120 N), the speeds by 4e-8 rad/s, the angles by 6e-13 rad.
// Before: FlankTable::flank_jet() evaluates its cubic Hermite from the power-basis coefficients
// (y0 + m0·t + c2·t² + c3·t³, Horner) instead of the four basis polynomials: 1.4 % fewer
// instructions per paper step, the same cubic to rounding — every hash changed; bench_contact_sweep
// over the paper's six meshes: depths within 5.5e-17 m, points within 1.1e-11 m of the former,
// stateless and continued alike.
// kGoldenHash is the rigid-body engine's (it runs with --set solver.engine=rigid_bodies).
constexpr std::uint64_t kGoldenHash = 0xd59c0bdd3056c399ull;
// The default engine's (multibody, trapezoid_closed, active_set, planar mass matrix) hash.
constexpr std::uint64_t kGoldenHashMultibody = 0xfdfbca74e294871full;
// The same with --set solver.mass_matrix=articulated (Bullet's articulated-body pass and tree walks).
constexpr std::uint64_t kGoldenHashMultibodyArticulated = 0xca89cb5eab98b877ull;
// The multibody engine with implicit Euler (θ = 1) and Dantzig, the defaults before.
constexpr std::uint64_t kGoldenHashImplicitEuler = 0xb4d3d0aae7b50160ull;
// Without the continuation (--set contact.continued_search=false): the coherent search's and the
// stateless search's, the same physics since Newton's refinement came in (multibody with θ = 1).
constexpr std::uint64_t kGoldenHashSampled = 0xc3467939069c6287ull;
constexpr std::uint64_t kGoldenHashSampledMultibody = 0x6aed78b6c01d6f55ull;

TEST(RunDeterminism, SameScenarioGivesByteIdenticalLogs) {
  const fs::path a = run_paper("a"), b = run_paper("b");
  EXPECT_EQ(hash_files(a), hash_files(b));
}

std::string hex_of(std::uint64_t h) {
  char hex[32];
  std::snprintf(hex, sizeof hex, "0x%016llxull", static_cast<unsigned long long>(h));
  return hex;
}

TEST(RunDeterminism, ShortPaperRunMatchesTheCommittedHash) {
  const std::uint64_t h = hash_files(run_paper("golden"));
  EXPECT_EQ(h, kGoldenHashMultibody) << "logs of the short paper run changed; new hash " << hex_of(h);
}

TEST(RunDeterminism, TheArticulatedMassMatrixStillGivesItsCommittedHash) {
  const std::uint64_t h = hash_files(run_paper("golden_articulated", " --set solver.mass_matrix=articulated"));
  EXPECT_EQ(h, kGoldenHashMultibodyArticulated) << "logs of the short paper run (mass_matrix articulated) changed; new hash " << hex_of(h);
}

TEST(RunDeterminism, ImplicitEulerStillGivesItsCommittedHash) {
  const std::uint64_t h = hash_files(run_paper("golden_theta", " --set solver.integrator=theta --set solver.row_solver=dantzig"));
  EXPECT_EQ(h, kGoldenHashImplicitEuler) << "logs of the short paper run (integrator theta) changed; new hash " << hex_of(h);
}

TEST(RunDeterminism, TheRigidBodyEngineStillGivesItsCommittedHash) {
  const std::uint64_t h = hash_files(run_paper("golden_rigid", " --set solver.engine=rigid_bodies"));
  EXPECT_EQ(h, kGoldenHash) << "logs of the short paper run (rigid_bodies) changed; new hash " << hex_of(h);
}

TEST(RunDeterminism, TheStatelessContactSearchGivesTheSameLogs) {
  // contact.coherent_search (default true) skips and tracks flanks only where that provably
  // changes nothing: without the continuation, it and the stateless search give the same bytes,
  // with either engine — the ones they gave before the continuation came in (multibody: θ = 1).
  const std::string sampled = " --set contact.continued_search=false", theta = " --set solver.integrator=theta --set solver.row_solver=dantzig";
  EXPECT_EQ(hash_files(run_paper("coherent", sampled + theta)), kGoldenHashSampledMultibody);
  EXPECT_EQ(hash_files(run_paper("stateless", " --set contact.coherent_search=false" + theta)), kGoldenHashSampledMultibody);
  EXPECT_EQ(hash_files(run_paper("coherent_rigid", sampled + " --set solver.engine=rigid_bodies")), kGoldenHashSampled);
  EXPECT_EQ(hash_files(run_paper("stateless_rigid", " --set contact.coherent_search=false --set solver.engine=rigid_bodies")), kGoldenHashSampled);
}

}  // namespace test_run_determinism
