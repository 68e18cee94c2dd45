// The housing accelerometer (McFadden & Smith's planet-pass model) on the paper's set: its window,
// and the spectrum it sees. Three equally spaced planets meshing in phase with a 96-tooth ring
// (96 ≡ 0 mod 3): around every mesh harmonic k·f_m only the sidebands n·f_c with n ≡ 0 (mod 3)
// survive at a fixed sensor, the others cancel; the flawed planet breaks the symmetry and fills
// them in.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <complex>
#include <fstream>
#include <numbers>
#include <sstream>

#include "analysis/planet_pass.hpp"
#include "input/scenario_file.hpp"
#include "sim/sensor_log.hpp"
#include "sim/simulate.hpp"
#include "sim/step_log.hpp"
#include "tests/support/asset_scenario.hpp"

namespace gearsim {
namespace test_sensor_log {

TEST(SensorLog, ThePlanetPassWindowIsAHannOfTheAngleToTheSensor) {
  const Eigen::Vector2d c(0, 0);
  const double w = 2 * std::numbers::pi / 3, up = std::numbers::pi / 2;
  EXPECT_DOUBLE_EQ(sim::planet_pass_window({0, 0.05}, c, up, w), 1.0);  // under the sensor
  EXPECT_NEAR(sim::planet_pass_window({0.05 * std::cos(up + w / 4), 0.05 * std::sin(up + w / 4)}, c, up, w), 0.5, 1e-12);
  EXPECT_EQ(sim::planet_pass_window({0, -0.05}, c, up, w), 0.0);  // opposite
}

// The sensor's amplitude at f (Hz) over t ≥ 0.1 s of sensors.csv (Hann, coherent gain corrected).
struct SensorRecord {
  std::vector<double> x;
  double fs = 0;
  double amplitude(double f) const {
    std::complex<double> acc = 0, ph = 1;
    const std::complex<double> step = std::polar(1.0, -2 * std::numbers::pi * f / fs);
    const std::size_t n = x.size();
    for (std::size_t i = 0; i < n; ++i, ph *= step)
      acc += x[i] * (0.5 - 0.5 * std::cos(2 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n - 1))) * ph;
    return 4 * std::abs(acc) / static_cast<double>(n);
  }
};

SensorRecord run_sensor(const std::string& asset) {
  const std::filesystem::path dir = test::fresh_test_dir();
  const physics::Scenario s =
      input::load_scenario(std::filesystem::path(GEARSIM_SOURCE_DIR) / "assets/scenarios" / asset, {"output.per_step_log=false"});
  sim::SensorLog log(dir, s);
  const sim::RunSummary r = sim::simulate(s, {&log});
  EXPECT_EQ(r.status, sim::RunStatus::Completed);
  std::ifstream in(dir / "sensors.csv");
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "time_s,housing_top_acceleration_m_s2");
  SensorRecord rec;
  rec.fs = s.sensors.front().sample_rate_hz;
  double mean = 0;
  while (std::getline(in, line)) {
    std::istringstream row(line);
    double t = 0, a = 0;
    char comma = 0;
    row >> t >> comma >> a;
    if (t >= 0.1) rec.x.push_back(a), mean += a;
  }
  for (double& v : rec.x) v -= mean / static_cast<double>(rec.x.size());
  return rec;
}

TEST(SensorLog, InPhasePlanetsLeaveOnlyEveryThirdSidebandAndTheFlawFillsTheRestIn) {
  const double fc = 104.7 / 5 / (2 * std::numbers::pi), fm = 96 * fc;
  const SensorRecord healthy = run_sensor("paper_dynamics_healthy.yaml");
  const SensorRecord faulty = run_sensor("paper_dynamics.yaml");
  for (int k = 1; k <= 3; ++k) {
    double kept = 0, cancelled = 0, faulty_cancelled = 0;
    for (int n = -3; n <= 3; ++n) {
      const double f = k * fm + n * fc;
      if (planet_pass_line_survives(3, 96, k, n))
        kept = std::max(kept, healthy.amplitude(f));
      else
        cancelled = std::max(cancelled, healthy.amplitude(f)), faulty_cancelled = std::max(faulty_cancelled, faulty.amplitude(f));
    }
    EXPECT_LT(20 * std::log10(cancelled / kept), -20.0) << "harmonic " << k;
    EXPECT_GT(20 * std::log10(faulty_cancelled / cancelled), 10.0) << "harmonic " << k;
  }
}

// Sequential meshing (sun 25, ring 95): around k·f_m only n ≡ −95k ≡ k (mod 3) survive — the
// pattern shifted off the mesh line, as McFadden & Smith predict; every cancelled line ≥ 20 dB
// below the survivors.
TEST(SensorLog, SequentialPlanetsShiftTheSurvivingSidebandsAsPredicted) {
  const double fc = 104.7 / 4.8 / (2 * std::numbers::pi), fm = 95 * fc;
  const SensorRecord rec = run_sensor("sequential_planetary.yaml");
  for (int k = 1; k <= 3; ++k) {
    double kept = 0, cancelled = 0;
    for (int n = -5; n <= 5; ++n) {
      const double a = rec.amplitude(k * fm + n * fc);
      if (planet_pass_line_survives(3, 95, k, n))
        kept = std::max(kept, a);
      else
        cancelled = std::max(cancelled, a);
    }
    EXPECT_LT(20 * std::log10(cancelled / kept), -20.0) << "harmonic " << k;
  }
  // The mesh line itself (n = 0) cancels at k = 1 and 2, survives at k = 3.
  EXPECT_FALSE(planet_pass_line_survives(3, 95, 1, 0));
  EXPECT_TRUE(planet_pass_line_survives(3, 95, 3, 0));
}

}  // namespace test_sensor_log
}  // namespace gearsim

namespace gearsim {
namespace test_sensor_log {

// The per-step log records each sensor's acceleration at every step, before the acquisition
// (anti-aliasing filter, decimation, noise). Sampled at the step rate without noise the
// acquisition is the identity, so sensors.csv and steps.h5 /sensors hold the same numbers; at
// 25 kHz (every second step) steps.h5 still has one row per step.
std::vector<double> read_sensor_dataset(const std::filesystem::path& h5, std::string* columns) {
  const hid_t file = H5Fopen(h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  EXPECT_GE(file, 0) << h5;
  const hid_t d = H5Dopen2(file, "sensors", H5P_DEFAULT);
  EXPECT_GE(d, 0) << "no /sensors in " << h5;
  const hid_t space = H5Dget_space(d);
  std::vector<double> out(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
  H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data());
  const hid_t a = H5Aopen(d, "columns", H5P_DEFAULT);
  const hid_t t = H5Aget_type(a);
  std::string text(H5Tget_size(t), '\0');
  H5Aread(a, t, text.data());
  *columns = text.c_str();
  H5Tclose(t), H5Aclose(a), H5Sclose(space), H5Dclose(d), H5Fclose(file);
  return out;
}

std::vector<double> run_with_step_log(const std::string& rate, const std::filesystem::path& dir, long* steps, std::string* columns) {
  const physics::Scenario s = input::load_scenario(std::string(GEARSIM_SOURCE_DIR) + "/assets/scenarios/paper_dynamics_healthy.yaml",
                                                   {"duration_s=0.01", "sensors[0].sample_rate_hz=" + rate});
  sim::SensorLog sensors(dir, s);
  sim::StepLogObserver step_log(dir / "steps.h5", s.name, s.solver.time_step_s);
  step_log.log_sensors(&sensors);
  const sim::RunSummary r = sim::simulate(s, {&sensors, &step_log});
  EXPECT_EQ(r.status, sim::RunStatus::Completed);
  *steps = r.steps;
  return read_sensor_dataset(dir / "steps.h5", columns);
}

TEST(SensorLog, TheStepLogHoldsEverySensorsAccelerationAtEveryStep) {
  const std::filesystem::path dir = test::fresh_test_dir();
  long steps = 0;
  std::string columns;
  const std::vector<double> logged = run_with_step_log("50000", dir, &steps, &columns);  // dt 2e-5 s: the step rate
  EXPECT_EQ(columns, "housing_top_acceleration_m_s2");
  ASSERT_EQ(static_cast<long>(logged.size()), steps);
  std::ifstream csv(dir / "sensors.csv");
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "time_s,housing_top_acceleration_m_s2");
  std::size_t row = 0;
  double largest = 0;
  while (std::getline(csv, line)) {
    const double value = std::stod(line.substr(line.find(',') + 1));
    ASSERT_LT(row, logged.size());
    EXPECT_EQ(value, logged[row]) << "step " << row + 1;
    largest = std::max(largest, std::abs(value));
    ++row;
  }
  EXPECT_EQ(static_cast<long>(row), steps);
  EXPECT_GT(largest, 0.0);  // the meshes load the housing: a signal, not zeros

  const std::filesystem::path dir25 = test::fresh_test_dir();
  const std::vector<double> logged25 = run_with_step_log("25000", dir25, &steps, &columns);
  EXPECT_EQ(static_cast<long>(logged25.size()), steps);  // one per step, whatever the acquisition rate
  EXPECT_EQ(logged25, logged);  // the same signal before acquisition
}

}  // namespace test_sensor_log
}  // namespace gearsim
