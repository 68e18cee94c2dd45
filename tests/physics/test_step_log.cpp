// The HDF5 per-step log holds exactly what the world reported, readable with the plain HDF5 API.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <filesystem>
#include <vector>

#include "app/scenario_file.hpp"
#include "physics/step_log.hpp"

namespace gearsim::physics {
namespace {

std::vector<double> read_doubles(hid_t file, const char* name, hsize_t* dims_out = nullptr) {
  const hid_t d = H5Dopen2(file, name, H5P_DEFAULT);
  const hid_t space = H5Dget_space(d);
  hsize_t dims[2] = {0, 1};
  const int rank = H5Sget_simple_extent_dims(space, dims, nullptr);
  std::vector<double> out(dims[0] * (rank == 2 ? dims[1] : 1));
  H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data());
  if (dims_out) dims_out[0] = dims[0], dims_out[1] = rank == 2 ? dims[1] : 1;
  H5Sclose(space);
  H5Dclose(d);
  return out;
}

TEST(StepLog, HoldsEveryStepAndEveryToothContact) {
  const Scenario s = app::load_scenario(std::string(GEARSIM_SOURCE_DIR) + "/assets/scenarios/paper_dynamics_healthy.yaml",
                                       {"duration_s=0.0024"});
  const std::filesystem::path path = std::filesystem::temp_directory_path() / "gearsim_step_log_test.h5";
  World world(s);
  std::vector<double> forces;  // every contact's normal force, in order
  constexpr int kSteps = 120;
  {
    StepLog log(path, world, s.name, s.solver.time_step_s);
    for (int i = 0; i < kSteps; ++i) {
      world.step();
      log.append(world);
      for (const ContactSample& c : world.contacts()) forces.push_back(c.normal_force_N);
    }
    log.close();
  }
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  hsize_t dims[2];
  const std::vector<double> state = read_doubles(file, "state", dims);
  EXPECT_EQ(dims[0], static_cast<hsize_t>(kSteps));
  EXPECT_EQ(dims[1], 1 + 2 * world.bodies().size());
  EXPECT_DOUBLE_EQ(state[(kSteps - 1) * dims[1]], world.time_s());
  const std::vector<double> impulses = read_doubles(file, "contacts/normal_impulse_N_s");
  ASSERT_EQ(impulses.size(), forces.size());
  ASSERT_FALSE(forces.empty());
  // Stored as impulse = force × dt: exact up to one rounding.
  for (std::size_t i = 0; i < forces.size(); ++i)
    EXPECT_NEAR(impulses[i] / s.solver.time_step_s, forces[i], 1e-12 * std::abs(forces[i]) + 1e-12);
  H5Fclose(file);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace gearsim::physics
