// steps.h5 format 2 (docs/hdf5-log.md): every column read back gives what the world reported, to
// the column's stated resolution (float32: one rounding, ≤ 2^-24 relative; float64 and integers:
// exact); a run cut short by an exception or an early close leaves a readable file holding every
// appended step; the same run gives the same bytes.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include "input/scenario_file.hpp"
#include "sim/step_log.hpp"
#include "sim/step_log_reader.hpp"

namespace gearsim::sim {
namespace test_step_log_round_trip {

namespace fs = std::filesystem;

physics::Scenario paper() {
  return input::load_scenario(std::string(GEARSIM_SOURCE_DIR) + "/assets/scenarios/paper_dynamics_healthy.yaml", {"duration_s=0.1"});
}

// What the world reported, step by step and contact by contact, in the log's order.
struct Reference {
  std::vector<double> time_s, state;  // per step; state: angle, speed of every body
  std::vector<std::int64_t> step, pair, tooth_a, tooth_b, flank_a;
  std::vector<std::vector<double>> values;  // per contact: the float columns in kFloat32 order, then the impulse
};

const char* const kFloat32[] = {"point_x_m", "point_y_m", "normal_x", "normal_y", "depth_m", "friction_impulse_N_s"};

void record(const physics::World& w, double dt, Reference& r) {
  r.time_s.push_back(w.time_s());
  for (const physics::BodyState& b : w.bodies()) r.state.push_back(b.angle_rad), r.state.push_back(b.speed_rad_s);
  for (const physics::ContactSample& c : w.contacts()) {
    r.step.push_back(w.steps());
    r.pair.push_back(c.pair);
    r.tooth_a.push_back(c.geometry.tooth_a);
    r.tooth_b.push_back(c.geometry.tooth_b);
    r.flank_a.push_back(c.geometry.flank_a == Flank::Ccw ? 0 : 1);
    r.values.push_back({c.geometry.point_m.x(), c.geometry.point_m.y(), c.geometry.normal_on_b.x(), c.geometry.normal_on_b.y(),
                        c.geometry.depth_m, c.friction_force_N * dt, c.normal_force_N * dt});
  }
}

// Steps the world `steps` times, appending each step to the log (left open: the caller closes it
// or lets it go out of scope) and to the reference.
void run(physics::World& world, StepLog& log, int steps, double dt, Reference& r) {
  for (int i = 0; i < steps; ++i) {
    world.step();
    log.append(world);
    record(world, dt, r);
  }
}

hid_t dataset_type(hid_t file, const char* name) {
  const hid_t d = H5Dopen2(file, name, H5P_DEFAULT);
  const hid_t t = H5Dget_type(d);
  H5Dclose(d);
  return t;
}

template <class T>
std::vector<T> read(hid_t file, const char* name, hid_t memtype) {
  const hid_t d = H5Dopen2(file, name, H5P_DEFAULT);
  const hid_t space = H5Dget_space(d);
  std::vector<T> out(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
  H5Dread(d, memtype, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data());
  H5Sclose(space);
  H5Dclose(d);
  return out;
}

bool same_type(hid_t file, const char* name, hid_t expected) {
  const hid_t t = dataset_type(file, name);
  const bool same = H5Tequal(t, expected) > 0;
  H5Tclose(t);
  return same;
}

TEST(StepLogRoundTrip, EveryColumnReadsBackToItsStatedResolution) {
  const physics::Scenario s = paper();
  const double dt = s.solver.time_step_s;
  const fs::path path = fs::temp_directory_path() / "gearsim_step_log_round_trip.h5";
  physics::World world(s);
  Reference r;
  {
    StepLog log(path, world, s.name, dt);
    run(world, log, 300, dt, r);
    log.close();
  }
  ASSERT_FALSE(r.step.empty());
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  // The documented file types.
  EXPECT_TRUE(same_type(file, "state", H5T_IEEE_F64LE));
  EXPECT_TRUE(same_type(file, "contacts/step", H5T_STD_I32LE));
  EXPECT_TRUE(same_type(file, "contacts/pair", H5T_STD_I8LE));
  EXPECT_TRUE(same_type(file, "contacts/tooth_a", H5T_STD_I16LE));
  EXPECT_TRUE(same_type(file, "contacts/tooth_b", H5T_STD_I16LE));
  EXPECT_TRUE(same_type(file, "contacts/flank_a", H5T_STD_I8LE));
  EXPECT_TRUE(same_type(file, "contacts/normal_impulse_N_s", H5T_IEEE_F64LE));
  for (const char* name : kFloat32) EXPECT_TRUE(same_type(file, (std::string("contacts/") + name).c_str(), H5T_IEEE_F32LE)) << name;
  // float64 and integers: exact.
  EXPECT_EQ(read<double>(file, "state", H5T_NATIVE_DOUBLE), r.state);
  EXPECT_EQ(read<std::int64_t>(file, "contacts/step", H5T_NATIVE_INT64), r.step);
  EXPECT_EQ(read<std::int64_t>(file, "contacts/pair", H5T_NATIVE_INT64), r.pair);
  EXPECT_EQ(read<std::int64_t>(file, "contacts/tooth_a", H5T_NATIVE_INT64), r.tooth_a);
  EXPECT_EQ(read<std::int64_t>(file, "contacts/tooth_b", H5T_NATIVE_INT64), r.tooth_b);
  EXPECT_EQ(read<std::int64_t>(file, "contacts/flank_a", H5T_NATIVE_INT64), r.flank_a);
  const std::vector<double> impulse = read<double>(file, "contacts/normal_impulse_N_s", H5T_NATIVE_DOUBLE);
  ASSERT_EQ(impulse.size(), r.values.size());
  for (std::size_t c = 0; c < impulse.size(); ++c) EXPECT_EQ(impulse[c], r.values[c][6]) << "row " << c;
  // float32: one rounding to nearest, so within half an ulp, 2^-24 of the value (for normal
  // floats, ≥ 1.2e-38: a logged value below that, but not zero, would fail here).
  for (std::size_t k = 0; k < std::size(kFloat32); ++k) {
    const std::vector<double> v = read<double>(file, (std::string("contacts/") + kFloat32[k]).c_str(), H5T_NATIVE_DOUBLE);
    ASSERT_EQ(v.size(), r.values.size()) << kFloat32[k];
    for (std::size_t c = 0; c < v.size(); ++c)
      ASSERT_LE(std::abs(v[c] - r.values[c][k]), std::ldexp(std::abs(r.values[c][k]), -24)) << kFloat32[k] << " row " << c;
  }
  H5Fclose(file);
  // Our reader: each row's time is its step's world.time_s(), bit for bit (the analysis compares it
  // with output-rate sample times).
  const StepLogContacts c = read_step_log_contacts(path);
  EXPECT_EQ(c.time_step_s, dt);
  EXPECT_EQ(c.pairs.size(), world.gear_pairs().size());
  ASSERT_EQ(c.time_s.size(), r.step.size());
  for (std::size_t i = 0; i < c.time_s.size(); ++i)
    ASSERT_EQ(c.time_s[i], r.time_s[static_cast<std::size_t>(r.step[i] - 1)]) << "row " << i;
  EXPECT_EQ(c.tooth_a, r.tooth_a);
  EXPECT_EQ(c.flank_a, r.flank_a);
  fs::remove(path);
}

// Rows on disk of /state and of /contacts/step.
struct OnDisk {
  std::size_t state_rows = 0, contact_rows = 0;
};

OnDisk on_disk(const fs::path& path) {
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  EXPECT_GE(file, 0) << path;
  OnDisk o;
  if (file < 0) return o;
  const hid_t d = H5Dopen2(file, "state", H5P_DEFAULT);
  const hid_t space = H5Dget_space(d);
  hsize_t dims[2] = {0, 0};
  H5Sget_simple_extent_dims(space, dims, nullptr);
  o.state_rows = dims[0];
  H5Sclose(space);
  H5Dclose(d);
  o.contact_rows = read<std::int64_t>(file, "contacts/step", H5T_NATIVE_INT64).size();
  H5Fclose(file);
  return o;
}

TEST(StepLogRoundTrip, AnExceptionMidRunLeavesEveryAppendedStep) {
  // More steps than one buffered write (4096) so the file holds written and buffered rows both.
  const physics::Scenario s = paper();
  const fs::path path = fs::temp_directory_path() / "gearsim_step_log_exception.h5";
  physics::World world(s);
  Reference r;
  constexpr int kSteps = 4096 + 37;
  try {
    StepLog log(path, world, s.name, s.solver.time_step_s);
    run(world, log, kSteps, s.solver.time_step_s, r);
    throw std::runtime_error("the run stops here");  // the log is never closed by hand
  } catch (const std::runtime_error&) {}
  const OnDisk o = on_disk(path);
  EXPECT_EQ(o.state_rows, static_cast<std::size_t>(kSteps));
  EXPECT_EQ(o.contact_rows, r.step.size());
  const StepLogContacts c = read_step_log_contacts(path);
  ASSERT_FALSE(c.step.empty());
  EXPECT_EQ(c.step.back(), r.step.back());
  EXPECT_EQ(c.normal_impulse_N_s.back(), r.values.back()[6]);
  fs::remove(path);
}

TEST(StepLogRoundTrip, AnEarlyCloseLeavesEveryAppendedStepAndRefusesMore) {
  const physics::Scenario s = paper();
  const fs::path path = fs::temp_directory_path() / "gearsim_step_log_early_close.h5";
  physics::World world(s);
  Reference r;
  StepLog log(path, world, s.name, s.solver.time_step_s);
  run(world, log, 25, s.solver.time_step_s, r);
  log.close();
  // Readable while the StepLog still lives: close() wrote and released everything.
  const OnDisk o = on_disk(path);
  EXPECT_EQ(o.state_rows, 25u);
  EXPECT_EQ(o.contact_rows, r.step.size());
  world.step();
  EXPECT_THROW(log.append(world), InternalError);
  fs::remove(path);
}

std::string bytes_of(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

TEST(StepLogRoundTrip, TheSameRunGivesTheSameBytes) {
  const physics::Scenario s = paper();
  std::vector<std::string> files;
  for (const char* name : {"gearsim_step_log_same_a.h5", "gearsim_step_log_same_b.h5"}) {
    const fs::path path = fs::temp_directory_path() / name;
    physics::World world(s);
    Reference r;
    {
      StepLog log(path, world, s.name, s.solver.time_step_s);
      run(world, log, 200, s.solver.time_step_s, r);
    }
    files.push_back(bytes_of(path));
    fs::remove(path);
  }
  ASSERT_FALSE(files[0].empty());
  EXPECT_TRUE(files[0] == files[1]);
}

}  // namespace test_step_log_round_trip
}  // namespace gearsim::sim
