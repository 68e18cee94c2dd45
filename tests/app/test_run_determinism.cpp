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
                          "/assets/scenarios/paper_dynamics_healthy.yaml --out " + dir.string() + " --duration 0.004 --no-analyze" + extra +
                          " > /dev/null 2>&1";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  return dir;
}

// The hash of the 0.004 s paper run (200 steps) on Debian 12 / x86-64 with this build. Update
// it (the failure message prints the new value) only together with the change that explains it,
// and say in that commit's message what moved and by how much (forces, depths, the paper
// figures): the history of the hashes is the history of those commits.
// kGoldenHash is the rigid-body engine's (it runs with --set solver.engine=rigid_bodies).
constexpr std::uint64_t kGoldenHash = 0xd59c0bdd3056c399ull;
// The default engine's (multibody, trapezoid_closed, active_set, planar mass matrix) hash.
constexpr std::uint64_t kGoldenHashMultibody = 0xfdfbca74e294871full;
// The same with --set verify.mass_matrix=articulated (Bullet's articulated-body pass and tree walks).
constexpr std::uint64_t kGoldenHashMultibodyArticulated = 0xca89cb5eab98b877ull;
// The multibody engine with implicit Euler (θ = 1) and Dantzig's pivoting.
constexpr std::uint64_t kGoldenHashImplicitEuler = 0xb4d3d0aae7b50160ull;
// Without the continuation (--set verify.continued_search=false): the coherent search's and the
// stateless search's, the same physics (multibody with θ = 1).
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
  const std::uint64_t h = hash_files(run_paper("golden_articulated", " --set verify.mass_matrix=articulated"));
  EXPECT_EQ(h, kGoldenHashMultibodyArticulated) << "logs of the short paper run (mass_matrix articulated) changed; new hash " << hex_of(h);
}

TEST(RunDeterminism, ImplicitEulerStillGivesItsCommittedHash) {
  const std::uint64_t h = hash_files(run_paper("golden_theta", " --set solver.integrator=theta --set verify.row_solver=dantzig"));
  EXPECT_EQ(h, kGoldenHashImplicitEuler) << "logs of the short paper run (integrator theta) changed; new hash " << hex_of(h);
}

TEST(RunDeterminism, TheRigidBodyEngineStillGivesItsCommittedHash) {
  const std::uint64_t h = hash_files(run_paper("golden_rigid", " --set solver.engine=rigid_bodies"));
  EXPECT_EQ(h, kGoldenHash) << "logs of the short paper run (rigid_bodies) changed; new hash " << hex_of(h);
}

TEST(RunDeterminism, TheStatelessContactSearchGivesTheSameLogs) {
  // verify.coherent_search (default true) skips and tracks flanks only where that provably
  // changes nothing: without the continuation, it and the stateless search give the same bytes,
  // with either engine (multibody: θ = 1).
  const std::string sampled = " --set verify.continued_search=false",
                    theta = " --set solver.integrator=theta --set verify.row_solver=dantzig";
  EXPECT_EQ(hash_files(run_paper("coherent", sampled + theta)), kGoldenHashSampledMultibody);
  EXPECT_EQ(hash_files(run_paper("stateless", " --set verify.coherent_search=false" + theta)), kGoldenHashSampledMultibody);
  EXPECT_EQ(hash_files(run_paper("coherent_rigid", sampled + " --set solver.engine=rigid_bodies")), kGoldenHashSampled);
  EXPECT_EQ(hash_files(run_paper("stateless_rigid", " --set verify.coherent_search=false --set solver.engine=rigid_bodies")),
            kGoldenHashSampled);
}

}  // namespace test_run_determinism
