// McFadden's planet separation on a synthetic sensor record: three planets passing a sensor,
// sequentially phased (each planet's turn offset by a third), each heard through a Hann window of
// its distance from the sensor; planet 0 alone carries an impulse once per turn when its tooth 5
// faces the sun. Planet 0's separated average holds the impulse (FM4 far above 3), the others'
// do not, and the sensor analysis names planet 0 and tooth 5.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "analysis/planet_separation.hpp"
#include "analysis/sensor_analysis.hpp"
#include "core/errors.hpp"
#include "synthetic_signals.hpp"

namespace gearsim {
namespace test_planet_separation {

constexpr double kTwoPi = 2 * std::numbers::pi;
constexpr int kTeeth = 36;

struct Synthetic {
  RunSignals signals;
  TrainDescription train;
  SensorSignal sensor;
};

Synthetic synthetic() {
  Synthetic s;
  const double fs = 20000, fc = 3.0, f_spin = 8.0;  // carrier turns/s, planet turns/s relative to it
  const std::size_t n = static_cast<std::size_t>(4.0 * fs);  // 4 s: 12 passes per planet
  const double sensor_angle = std::numbers::pi / 2, width = kTwoPi / 3;
  s.sensor = {"top", sensor_angle, width, 0, {}, {}};
  std::vector<double> carrier(n), spin0(n), spin1(n), spin2(n);
  const auto noise = test::white_noise(n, 0.05, 2);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / fs;
    s.sensor.time_s.push_back(t);
    carrier[i] = kTwoPi * fc * t;
    double x = noise[i];
    for (int p = 0; p < 3; ++p) {
      const double position = carrier[i] + kTwoPi * p / 3;
      const double spin = kTwoPi * f_spin * t + kTwoPi * p / 3;  // sequential phasing
      (p == 0 ? spin0 : p == 1 ? spin1 : spin2)[i] = spin;
      const double delta = std::remainder(position - sensor_angle, kTwoPi);
      const double w = std::abs(delta) < width / 2 ? 0.5 * (1 + std::cos(kTwoPi * delta / width)) : 0.0;
      double mesh = std::cos(kTeeth * spin);
      // Planet 0's tooth 5 faces the sun at spin = −5·pitch (sun_direction 0): an impulse there.
      if (p == 0) {
        const double from = std::remainder(spin + 5 * kTwoPi / kTeeth, kTwoPi) / (kTwoPi / kTeeth);
        mesh += 3 * std::exp(-0.5 * std::pow(from / 0.05, 2));
      }
      x += w * mesh;
    }
    s.sensor.acceleration_m_s2.push_back(x);
  }
  s.signals.time_s = s.sensor.time_s;
  s.signals.angles = {{"carrier", carrier}, {"planet_0", spin0}, {"planet_1", spin1}, {"planet_2", spin2}};
  s.train.planetary = true;
  s.train.carrier = "carrier";
  for (int p = 0; p < 3; ++p) s.train.planets.push_back({"planet_" + std::to_string(p), kTeeth, 0.0, kTwoPi * p / 3});
  return s;
}

TEST(PlanetSeparation, EachPlanetsAverageHoldsOnlyItsOwnEvents) {
  const Synthetic s = synthetic();
  std::vector<double> fm4;
  for (int p = 0; p < 3; ++p) {
    std::vector<double> position(s.sensor.time_s.size());
    for (std::size_t i = 0; i < position.size(); ++i) position[i] = s.signals.angles[0].angle_rad[i] + kTwoPi * p / 3;
    const PlanetSeparatedAverage a = planet_separated_average(s.sensor.acceleration_m_s2, position, s.signals.angles[1 + p].angle_rad,
                                                              s.sensor.angle_rad, s.sensor.window_width_rad, 1024);
    EXPECT_NEAR(a.passes, 12, 1) << p;
    EXPECT_DOUBLE_EQ(a.coverage, 1.0) << p;
    fm4.push_back(condition_indicators(a.mean, kTeeth).fm4);
  }
  EXPECT_GT(fm4[0], 10.0);
  EXPECT_LT(fm4[1], 4.0);
  EXPECT_LT(fm4[2], 4.0);
}

TEST(PlanetSeparation, TheSensorAnalysisNamesThePlanetAndTheTooth) {
  const Synthetic s = synthetic();
  const SensorAnalysis a = analyse_sensor(s.sensor, s.signals, s.train);
  ASSERT_TRUE(a.fault) << a.note;
  EXPECT_EQ(a.fault->gear, "planet_0");
  EXPECT_EQ(a.fault->tooth, 5);
  EXPECT_GT(a.fault->confidence, 0.5);
}

TEST(PlanetSeparation, BadInputIsRefused) {
  EXPECT_THROW(planet_separated_average({1, 2}, {0, 0}, {0}, 0, 1, 64), InputError);
  EXPECT_THROW(planet_separated_average({1, 2}, {3, 3}, {0, 1}, 0, 1, 64), InputError);  // never passes
}

}  // namespace test_planet_separation
}  // namespace gearsim

namespace gearsim {
namespace test_planet_separation {

// The sun's average: sun tooth 7 strikes whichever planet it meets (sun turn relative to the
// carrier minus that planet's place on the carrier = tooth 7's angle), heard through that
// planet's window; every window credits its samples to the sun tooth then meeting its planet.
TEST(PlanetSeparation, TheSunsAverageGathersItsToothFromEveryPlanetsWindow) {
  const double fs = 20000, fc = 3.0, f_sun = 12.0;  // turns per second; the sun's relative to the carrier
  const int z_sun = 24;
  const std::size_t n = static_cast<std::size_t>(4.0 * fs);
  const double sensor = std::numbers::pi / 2, width = kTwoPi / 3;
  std::vector<std::vector<double>> positions(3, std::vector<double>(n));
  std::vector<double> offsets{0, kTwoPi / 3, 2 * kTwoPi / 3}, sun(n), faulty(n), healthy(n);
  const auto noise = test::white_noise(n, 0.05, 4);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / fs;
    sun[i] = kTwoPi * f_sun * t;
    healthy[i] = faulty[i] = noise[i];
    for (int p = 0; p < 3; ++p) {
      positions[p][i] = kTwoPi * fc * t + offsets[p];
      const double delta = std::remainder(positions[p][i] - sensor, kTwoPi);
      const double w = std::abs(delta) < width / 2 ? 0.5 * (1 + std::cos(kTwoPi * delta / width)) : 0.0;
      const double meets = sun[i] - offsets[p];  // the sun's angle at planet p, relative to the carrier
      const double mesh = std::cos(z_sun * meets);
      const double from7 = std::remainder(meets - 7 * kTwoPi / z_sun, kTwoPi) / (kTwoPi / z_sun);
      healthy[i] += w * mesh;
      faulty[i] += w * (mesh + 3 * std::exp(-0.5 * std::pow(from7 / 0.05, 2)));
    }
  }
  const PlanetSeparatedAverage h = sun_separated_average(healthy, positions, offsets, sun, sensor, width, 1024);
  const PlanetSeparatedAverage f = sun_separated_average(faulty, positions, offsets, sun, sensor, width, 1024);
  EXPECT_DOUBLE_EQ(f.coverage, 1.0);
  EXPECT_LT(condition_indicators(h.mean, z_sun).fm4, 4.0);
  EXPECT_GT(condition_indicators(f.mean, z_sun).fm4, 10.0);
  // The impulse sits where sun tooth 7 is: angle 7·2π/24 of the sun's turn.
  std::size_t at = 0;
  for (std::size_t j = 1; j < f.mean.size(); ++j)
    if (f.mean[j] > f.mean[at]) at = j;
  EXPECT_NEAR(static_cast<double>(at) / 1024 * z_sun, 7.0, 0.05);
}

}  // namespace test_planet_separation
}  // namespace gearsim
