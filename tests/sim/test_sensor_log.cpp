// The housing accelerometer (McFadden & Smith's planet-pass model) on the paper's set: its window,
// and the spectrum it sees. Three equally spaced planets meshing in phase with a 96-tooth ring
// (96 ≡ 0 mod 3): around every mesh harmonic k·f_m only the sidebands n·f_c with n ≡ 0 (mod 3)
// survive at a fixed sensor, the others cancel; the flawed planet breaks the symmetry and fills
// them in.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <fstream>
#include <numbers>
#include <sstream>

#include "analysis/planet_pass.hpp"
#include "input/scenario_file.hpp"
#include "sim/sensor_log.hpp"
#include "sim/simulate.hpp"
#include "tests/support/asset_scenario.hpp"

namespace gearsim {
namespace test_sensor_log {

TEST(SensorLog, ThePlanetPassWindowIsAHannOfTheAngleToTheSensor) {
  const Eigen::Vector2d c(0, 0);
  const double w = 2 * std::numbers::pi / 3, up = std::numbers::pi / 2;
  EXPECT_DOUBLE_EQ(sim::planet_pass_window({0, 0.05}, c, up, w), 1.0);                                       // under the sensor
  EXPECT_NEAR(sim::planet_pass_window({0.05 * std::cos(up + w / 4), 0.05 * std::sin(up + w / 4)}, c, up, w), 0.5, 1e-12);
  EXPECT_EQ(sim::planet_pass_window({0, -0.05}, c, up, w), 0.0);                                             // opposite
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
  const physics::Scenario s = input::load_scenario(std::filesystem::path(GEARSIM_SOURCE_DIR) / "assets/scenarios" / asset,
                                                   {"output.per_step_log=false"});
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
      if (planet_pass_line_survives(3, 96, k, n)) kept = std::max(kept, healthy.amplitude(f));
      else cancelled = std::max(cancelled, healthy.amplitude(f)), faulty_cancelled = std::max(faulty_cancelled, faulty.amplitude(f));
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
      if (planet_pass_line_survives(3, 95, k, n)) kept = std::max(kept, a);
      else cancelled = std::max(cancelled, a);
    }
    EXPECT_LT(20 * std::log10(cancelled / kept), -20.0) << "harmonic " << k;
  }
  // The mesh line itself (n = 0) cancels at k = 1 and 2, survives at k = 3.
  EXPECT_FALSE(planet_pass_line_survives(3, 95, 1, 0));
  EXPECT_TRUE(planet_pass_line_survives(3, 95, 3, 0));
}

}  // namespace test_sensor_log
}  // namespace gearsim
