// ccx subprocess and .dat reader: a plane-stress bar in tension against u = F L / (E A), and the
// error paths (missing ccx, missing deck, a failing deck or an unfinished nonlinear step surfaces
// the log's *ERROR line and the log path).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/errors.hpp"
#include "fe/ccx_dat.hpp"
#include "fe/constants.hpp"
#include "fe/process.hpp"

using namespace gearsim;
using namespace gearsim::fe;
namespace fs = std::filesystem;

namespace test_ccx_process {

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("gearsim_fe_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

// Bar L × h × t (m) of nx × 1 CPS4 elements, left edge held in x (corner also in y), right edge
// pulled by F (N) split over its two nodes. Prints displacements of the right edge.
void write_bar_deck(const fs::path& file, double L, double h, double t, int nx, double F) {
  std::ofstream o(file);
  o << "*NODE, NSET=NALL\n";
  for (int j = 0; j <= 1; ++j)
    for (int i = 0; i <= nx; ++i) o << 1 + i + j * (nx + 1) << ", " << L * i / nx << ", " << h * j << ", 0\n";
  o << "*ELEMENT, TYPE=CPS4, ELSET=EALL\n";
  for (int i = 0; i < nx; ++i) o << i + 1 << ", " << i + 1 << ", " << i + 2 << ", " << i + nx + 3 << ", " << i + nx + 2 << "\n";
  o << "*NSET, NSET=LEFT\n1, " << nx + 2 << "\n*NSET, NSET=RIGHT\n"
    << nx + 1 << ", " << 2 * nx + 2 << "\n*MATERIAL, NAME=STEEL\n*ELASTIC\n"
    << kYoungModulus_Pa << ", " << kPoissonRatio << "\n*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n"
    << t << "\n*BOUNDARY\nLEFT, 1, 1\n1, 2, 2\n"
    << "*STEP\n*STATIC\n*CLOAD\n"
    << nx + 1 << ", 1, " << F / 2 << "\n"
    << 2 * nx + 2 << ", 1, " << F / 2 << "\n*NODE PRINT, NSET=RIGHT\nU\n*END STEP\n";
}

// Uniform tension is reproduced exactly by bilinear plane-stress elements, so the FE tip
// displacement equals F L / (E h t) to the solver's print precision (7 significant digits → 1e-6
// relative; 1e-5 allowed).
TEST(CcxProcess, BarInTensionMatchesClosedForm) {
  if (find_executable("ccx").empty()) GTEST_SKIP() << "ccx not installed";
  const fs::path dir = fresh_dir("bar");
  const double L = 0.01, h = 0.001, t = 0.001, F = 1000.0;
  write_bar_deck(dir / "bar.inp", L, h, t, 10, F);
  const CcxRunResult r = run_ccx({"ccx", dir, "bar"});
  const auto blocks = read_dat(r.dat_path);
  const DatBlock& u = last_block(blocks, "displacements", "RIGHT");
  ASSERT_EQ(u.rows.size(), 2u);
  const double expect = F * L / (kYoungModulus_Pa * h * t);
  for (const auto& [id, v] : u.rows) EXPECT_NEAR(v.at(0), expect, 1e-5 * expect) << "node " << id;
}

TEST(CcxProcess, MissingExecutableIsInputError) {
  const fs::path dir = fresh_dir("noexe");
  try {
    run_ccx({"ccx_does_not_exist_gearsim", dir, "job"});
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("ccx_does_not_exist_gearsim"), std::string::npos);
  }
}

TEST(CcxProcess, MissingDeckIsInputError) {
  if (find_executable("ccx").empty()) GTEST_SKIP() << "ccx not installed";
  EXPECT_THROW(run_ccx({"ccx", fresh_dir("nodeck"), "job"}), InputError);
}

// A deck referring to an undefined material: ccx prints *ERROR, which must reach the exception.
TEST(CcxProcess, FailingDeckSurfacesLogError) {
  if (find_executable("ccx").empty()) GTEST_SKIP() << "ccx not installed";
  const fs::path dir = fresh_dir("bad");
  write_bar_deck(dir / "bad.inp", 0.01, 0.001, 0.001, 2, 1.0);
  std::stringstream ss;
  ss << std::ifstream(dir / "bad.inp").rdbuf();
  std::string deck = ss.str();
  deck.replace(deck.find("MATERIAL=STEEL\n0.001"), 14, "MATERIAL=NOPE");
  std::ofstream(dir / "bad.inp") << deck;
  try {
    run_ccx({"ccx", dir, "bad"});
    FAIL() << "expected ccx failure";
  } catch (const InputError&) {
    FAIL() << "a solver failure is not an input error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("*ERROR"), std::string::npos) << e.what();
  }
}

// A nonlinear step that cannot finish in the increments it is allowed (10 fixed increments of 0.1,
// at most 2): ccx stops with "max. # of increments reached"; the error quotes that line and names
// the log file, the way a non-converged increment (too many cutbacks) is reported.
TEST(CcxProcess, UnfinishedIncrementsAreASolverError) {
  if (find_executable("ccx").empty()) GTEST_SKIP() << "ccx not installed";
  const fs::path dir = fresh_dir("increments");
  write_bar_deck(dir / "inc.inp", 0.01, 0.001, 0.001, 2, 1.0);
  std::stringstream ss;
  ss << std::ifstream(dir / "inc.inp").rdbuf();
  std::string deck = ss.str();
  deck.replace(deck.find("*STEP\n*STATIC\n"), 14, "*STEP, NLGEOM, INC=2\n*STATIC\n0.1, 1., 0.1, 0.1\n");
  std::ofstream(dir / "inc.inp") << deck;
  try {
    run_ccx({"ccx", dir, "inc"});
    FAIL() << "expected ccx failure";
  } catch (const InputError&) {
    FAIL() << "a solver failure is not an input error";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("max. # of increments"), std::string::npos) << what;
    EXPECT_NE(what.find((dir / "inc.log").string()), std::string::npos) << what;
  }
}

}  // namespace test_ccx_process
