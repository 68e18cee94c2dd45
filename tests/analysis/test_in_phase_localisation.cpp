// The sensor-alone localisation for planets meshing in phase, on a synthetic housing record with a
// known transfer: three planets, all with tooth T facing the sun at the same instant, each heard
// through the Hann window of its distance from the sensor (the sensor model's); each planet's mesh
// is a tone at its tooth rate, and at tooth T planet j sheds ΔF while the other two take ΔF/2
// each — every event heard through the same impulse response (a housing mode's ringing). The
// analysis must name planet j, tooth T, and list the others as load-sharing responses; a record
// without the event, or with one sign on every planet (a sun tooth), names no planet.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "analysis/in_phase_localisation.hpp"
#include "analysis/sensor_analysis.hpp"
#include "synthetic_signals.hpp"

namespace gearsim {
namespace test_in_phase_localisation {

constexpr double kTwoPi = 2 * std::numbers::pi;
constexpr int kTeeth = 36;
constexpr int kTooth = 0;  // the tooth whose mesh carries the event on every planet

struct Synthetic {
  RunSignals signals;
  TrainDescription train;
  SensorSignal sensor;
  std::vector<double> window_gain;  // per planet: Σw²/Σw of its window weights at the event instants
};

// event_gain[k]: planet k's load change at the event, in units of ΔF (planet j: −1, others +½).
Synthetic synthetic(const std::vector<double>& event_gain) {
  Synthetic s;
  const double fs = 20000, fc = 3.0, f_spin = 8.0;  // Hz; carrier turns/s; planet turns/s relative to it
  const std::size_t n = static_cast<std::size_t>(4.0 * fs);  // 4 s: 12 passes per planet
  const double sensor_angle = std::numbers::pi / 2, width = kTwoPi / 3, dF = 3.0;
  // The transfer of a load step to the housing: a 2 kHz mode ringing down in 0.5 ms.
  auto response = [](double tau_s) { return tau_s < 0 ? 0.0 : std::sin(kTwoPi * 2000 * tau_s) * std::exp(-tau_s / 5e-4); };
  s.sensor = {"top", sensor_angle, width, 0, {}, {}};
  std::vector<double> carrier(n), spin(n);
  const auto noise = test::white_noise(n, 0.05, 3);
  // Tooth T faces the sun at spin = −T·2π/z (sun direction 0): at t = (m − T/z)/f_spin.
  const double period = 1 / f_spin, first = std::fmod(-static_cast<double>(kTooth) / kTeeth + 1, 1.0) * period;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / fs;
    s.sensor.time_s.push_back(t);
    carrier[i] = kTwoPi * fc * t;
    spin[i] = kTwoPi * f_spin * t;  // in phase: one spin for every planet
    const double since = std::fmod(t - first + 10 * period, period);
    double x = noise[i];
    for (int p = 0; p < 3; ++p) {
      const double delta = std::remainder(carrier[i] + kTwoPi * p / 3 - sensor_angle, kTwoPi);
      const double w = std::abs(delta) < width / 2 ? 0.5 * (1 + std::cos(kTwoPi * delta / width)) : 0.0;
      x += w * (std::cos(kTeeth * spin[i]) + event_gain[static_cast<std::size_t>(p)] * dF * response(since));
    }
    s.sensor.acceleration_m_s2.push_back(x);
  }
  for (int p = 0; p < 3; ++p) {
    double w1 = 0, w2 = 0;
    for (double te = first; te < static_cast<double>(n) / fs; te += period) {
      const double delta = std::remainder(kTwoPi * fc * te + kTwoPi * p / 3 - sensor_angle, kTwoPi);
      const double w = std::abs(delta) < width / 2 ? 0.5 * (1 + std::cos(kTwoPi * delta / width)) : 0.0;
      w1 += w, w2 += w * w;
    }
    s.window_gain.push_back(w2 / w1);
  }
  s.signals.time_s = s.sensor.time_s;
  s.signals.angles = {{"carrier", carrier}, {"planet_0", spin}, {"planet_1", spin}, {"planet_2", spin}};
  s.train.planetary = true;
  s.train.planets_in_phase = true;
  s.train.carrier = "carrier";
  for (int p = 0; p < 3; ++p) s.train.planets.push_back({"planet_" + std::to_string(p), kTeeth, 0.0, kTwoPi * p / 3});
  return s;
}

TEST(InPhaseLocalisation, TheSheddingPlanetIsNamedAndTheOthersAreResponses) {
  for (int j = 0; j < 3; ++j) {
    std::vector<double> gain(3, 0.5);
    gain[static_cast<std::size_t>(j)] = -1;
    const Synthetic s = synthetic(gain);
    const SensorAnalysis a = analyse_sensor(s.sensor, s.signals, s.train);
    const std::string planet = "planet_" + std::to_string(j);
    ASSERT_TRUE(a.fault) << planet << ": " << a.note;
    EXPECT_EQ(a.fault->gear, planet);
    EXPECT_EQ(a.fault->tooth, kTooth) << planet;
    // Exact ± copies of one waveform under 0.05 noise: every |correlation| near 1.
    EXPECT_GT(a.fault->confidence, 0.9) << planet;
    // Planet j's load change is twice each other's; each average hears its events through its
    // window's weight at the event instants: the average at the event is Σw·(w·ΔF·h)/Σw, a gain
    // G_k = Σw²/Σw over planet k's events. So the ratio is 2·G_j/G_k, within 10 %: 2500 samples
    // per turn on the 4096-bin grid leave bins to linear interpolation, which cuts a 2 kHz ringing
    // sampled 10 times a cycle by up to 1 − cos(π/10) ≈ 5 % — differently in each planet's average.
    const InPhaseLocalisation& l = *a.in_phase;
    for (int k = 0; k < 3; ++k) {
      if (k == j) continue;
      const double ratio = l.planets[static_cast<std::size_t>(j)].event_rms_m_s2 / l.planets[static_cast<std::size_t>(k)].event_rms_m_s2;
      const double expected = 2 * s.window_gain[static_cast<std::size_t>(j)] / s.window_gain[static_cast<std::size_t>(k)];
      EXPECT_NEAR(ratio / expected, 1.0, 0.10) << planet << " against planet_" << k;
    }
    ASSERT_EQ(a.responses.size(), 2u) << planet;
    for (const ToothResponse& r : a.responses) {
      EXPECT_NE(r.gear, planet);
      EXPECT_EQ(r.tooth, kTooth);
      EXPECT_EQ(r.source, "sensor top");
    }
  }
}

TEST(InPhaseLocalisation, NoEventNamesNoPlanet) {
  const Synthetic s = synthetic({0, 0, 0});
  const SensorAnalysis a = analyse_sensor(s.sensor, s.signals, s.train);
  EXPECT_FALSE(a.fault) << a.fault->gear;
  EXPECT_TRUE(a.responses.empty());
  ASSERT_TRUE(a.in_phase);
  EXPECT_FALSE(a.in_phase->event);
}

// A sun tooth (or a torque step) loads every planet's mesh the same way at once: one polarity
// everywhere, no load handed from one planet to the others.
TEST(InPhaseLocalisation, OneSignOnEveryPlanetNamesNoPlanet) {
  const Synthetic s = synthetic({1, 1, 1});
  const SensorAnalysis a = analyse_sensor(s.sensor, s.signals, s.train);
  EXPECT_FALSE(a.fault) << a.fault->gear;
  ASSERT_TRUE(a.in_phase);
  EXPECT_TRUE(a.in_phase->event);
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t k = i + 1; k < 3; ++k) EXPECT_GT(a.in_phase->correlation[i][k], a.in_phase->min_correlation) << i << k;
}

TEST(InPhaseLocalisation, BadInputIsRefused) {
  EXPECT_THROW(localise_in_phase({std::vector<double>(256, 0.0)}, {0.0}, kTeeth, 1000), InputError);  // one planet
  EXPECT_THROW(localise_in_phase({std::vector<double>(256, 0.0), std::vector<double>(128, 0.0)}, {0.0, 0.0}, kTeeth, 1000), InputError);
  EXPECT_THROW(localise_in_phase({std::vector<double>(64, 0.0), std::vector<double>(64, 0.0)}, {0.0, 0.0}, kTeeth, 1000), InputError);
}

}  // namespace test_in_phase_localisation
}  // namespace gearsim
