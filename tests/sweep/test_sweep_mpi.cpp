// The same sweep run locally and under mpirun (1 master handing out cases + 2 workers) gives a
// byte-identical table: metrics are read back from each case's files and formatted one way.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <chrono>
#include <filesystem>

#include "tests/sweep/sweep_cli.hpp"
#include "tests/support/asset_scenario.hpp"
#include "tests/support/cli_run.hpp"

namespace gearsim::sweep {
namespace test_sweep_mpi {

namespace fs = std::filesystem;

bool have_mpirun() { return std::system("command -v mpirun > /dev/null 2>&1") == 0; }

TEST(SweepMpi, SameTableAsLocal) {
  if (!have_mpirun()) GTEST_SKIP() << "mpirun not installed (scripts/install-deps.sh installs openmpi-bin)";
  const fs::path dir = test::fresh_test_dir();
  const fs::path file =
      test::spur_sweep_file(dir,
                            "grid:\n  motors[0].target_speed_rad_s: [30, 45, 60]\n"
                            "  loads[0].constant_torque_N_m: [5, 10]\n"
                            "collect:\n  analysis: [transmission_error.peak_to_peak_rad]\n"
                            "  metrics: [dynamic_factor_band_limited, mean_force_N, mesh_frequency_hz, rms_dynamic_te_rad]\n");
  const test::CliRun local = test::gearsim("sweep " + file.string() + " --out " + (dir / "local").string() + " --jobs 2");
  ASSERT_EQ(local.exit_code, 0) << local.output;
  // As root, OpenMPI asks for both variables; --oversubscribe: 3 ranks on 2 cores.
  setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  const auto start = std::chrono::steady_clock::now();
  const test::CliRun mpi =
      test::gearsim_under("mpirun --oversubscribe -np 3 ", "sweep " + file.string() + " --out " + (dir / "mpi").string());
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_EQ(mpi.exit_code, 0) << mpi.output;
  EXPECT_NE(mpi.output.find("on 2 MPI workers"), std::string::npos) << mpi.output;
  EXPECT_LT(wall_s, 120.0);
  const std::string table = test::file_text(dir / "local/sweep.csv");
  EXPECT_EQ(test::file_text(dir / "mpi/sweep.csv"), table);
  // Six completed rows with every metric filled in: the comparison is not of empty columns.
  const auto rows = test::csv_rows(dir / "mpi/sweep.csv");
  ASSERT_EQ(rows.size(), 7u);
  for (std::size_t i = 1; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i][3], "completed") << i;
    for (std::size_t c = 4; c < rows[0].size(); ++c) EXPECT_FALSE(rows[i][c].empty()) << rows[0][c] << " of row " << i;
  }
}

}  // namespace test_sweep_mpi
}  // namespace gearsim::sweep
