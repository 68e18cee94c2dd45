// The HDF5 per-step log holds exactly what the world reported, readable with the plain HDF5 API.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cstdint>
#include <filesystem>
#include <vector>

#include "input/scenario_file.hpp"
#include "sim/step_log.hpp"

namespace gearsim::sim {
namespace test_step_log {

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
  const physics::Scenario s =
      input::load_scenario(std::string(GEARSIM_SOURCE_DIR) + "/assets/scenarios/paper_dynamics_healthy.yaml", {"duration_s=0.0024"});
  const std::filesystem::path path = std::filesystem::temp_directory_path() / "gearsim_step_log_test.h5";
  physics::World world(s);
  std::vector<double> forces;  // every contact's normal force, in order
  constexpr int kSteps = 120;
  {
    StepLog log(path, world, s.name, s.solver.time_step_s);
    for (int i = 0; i < kSteps; ++i) {
      world.step();
      log.append(world);
      for (const physics::ContactSample& c : world.contacts()) forces.push_back(c.normal_force_N);
    }
    log.close();
  }
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  hsize_t dims[2];
  const std::vector<double> state = read_doubles(file, "state", dims);
  EXPECT_EQ(dims[0], static_cast<hsize_t>(kSteps));
  EXPECT_EQ(dims[1], 2 * world.bodies().size());
  EXPECT_EQ(state[(kSteps - 1) * dims[1]], world.bodies().front().angle_rad);  // float64: exact
  const std::vector<double> impulses = read_doubles(file, "contacts/normal_impulse_N_s");
  ASSERT_EQ(impulses.size(), forces.size());
  ASSERT_FALSE(forces.empty());
  // Stored as impulse = force × dt in float64: exact up to one rounding.
  for (std::size_t i = 0; i < forces.size(); ++i)
    EXPECT_NEAR(impulses[i] / s.solver.time_step_s, forces[i], 1e-12 * std::abs(forces[i]) + 1e-12);
  H5Fclose(file);
  std::filesystem::remove(path);
}

std::vector<std::int64_t> read_ints(hid_t file, const char* name) {
  const hid_t d = H5Dopen2(file, name, H5P_DEFAULT);
  const hid_t space = H5Dget_space(d);
  std::vector<std::int64_t> out(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
  H5Dread(d, H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data());
  H5Sclose(space);
  H5Dclose(d);
  return out;
}

TEST(StepLog, LoggedContactsCarryTheMotorTorque) {
  // Read back from the file alone: Σ (p × n)·F over the sun's tooth contacts is the torque the
  // planets put on the sun; in steady running it balances the motor's torque. Friction off (its
  // impulses are logged as magnitudes without direction); sun at 50 rad/s, reached in 2 ms.
  const physics::Scenario s =
      input::load_scenario(std::string(GEARSIM_SOURCE_DIR) + "/assets/scenarios/paper_dynamics_healthy.yaml",
                           {"motors[0].target_speed_rad_s=50", "motors[0].ramp_time_s=0.002", "contact.friction=0"});
  const std::filesystem::path path = std::filesystem::temp_directory_path() / "gearsim_step_log_torque.h5";
  physics::World world(s);
  constexpr int kSteps = 500, kFrom = 100;  // average over 2–10 ms
  double motor = 0;
  {
    StepLog log(path, world, s.name, s.solver.time_step_s);
    for (int i = 1; i <= kSteps; ++i) {
      world.step();
      log.append(world);
      if (i > kFrom) motor += world.motor_torque_N_m("sun");
    }
  }
  motor /= kSteps - kFrom;
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  const std::vector<double> px = read_doubles(file, "contacts/point_x_m"), py = read_doubles(file, "contacts/point_y_m"),
                            nx = read_doubles(file, "contacts/normal_x"), ny = read_doubles(file, "contacts/normal_y"),
                            impulse = read_doubles(file, "contacts/normal_impulse_N_s");
  const std::vector<std::int64_t> step = read_ints(file, "contacts/step"), pair = read_ints(file, "contacts/pair");
  H5Fclose(file);
  std::filesystem::remove(path);
  // Pairs 0–2 are sun–planet with the sun as body a; the normal points from b toward a, so the
  // force on the sun is +n·F. The sun floats by a few µm: moments about the origin are exact to
  // ~1e-4 relative.
  double contact = 0;
  for (std::size_t c = 0; c < step.size(); ++c)
    if (pair[c] < 3 && step[c] > kFrom) contact += (px[c] * ny[c] - py[c] * nx[c]) * impulse[c] / s.solver.time_step_s;
  contact /= kSteps - kFrom;
  EXPECT_NEAR(motor, 20.0 / 5, 0.1);  // the carrier's 20 N·m over the ratio 5
  // Newton about the sun axis: motor + contacts = I·dω/dt, whose mean over 8 ms is below
  // 1e-4 N·m (I ≈ 1.4e-6 kg·m², speed ripple < 0.5 rad/s); 0.5 % covers the µm float of the sun.
  EXPECT_NEAR(contact, -motor, 0.005 * motor);
}

}  // namespace test_step_log
}  // namespace gearsim::sim
