// Angle-synchronous averaging under a fluctuating speed, both directions of rotation, and the
// per-tooth statistics that pick out one planted tooth anomaly.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "analysis/angle_average.hpp"
#include "analysis/tooth_statistics.hpp"
#include "core/errors.hpp"
#include "tests/analysis/synthetic_signals.hpp"

namespace gearsim {
namespace test_angle_average {

using test::kTwoPi;

constexpr double kFs = 20000.0;  // Hz
constexpr double kOmega = kTwoPi * 8.887;  // rad/s: the paper's planet relative to the carrier
constexpr double kWobble = 0.05, kWobbleHz = 2.3;  // rad, Hz: speed fluctuation (≤ 0.72 rad/s ≪ ω)
constexpr int kTeeth = 36;

// The reference body's angle at time t, turning the way `direction` (±1) says.
double body_angle(double t, double direction) { return direction * (kOmega * t + kWobble * std::sin(kTwoPi * kWobbleHz * t)); }

// Time samples covering `revolutions` turns.
std::vector<double> times(double revolutions) {
  const auto n = static_cast<std::size_t>(revolutions * kTwoPi / kOmega * kFs);
  std::vector<double> t(n);
  for (std::size_t i = 0; i < n; ++i) t[i] = static_cast<double>(i) / kFs;
  return t;
}

// A pattern locked to the body's angle φ.
double pattern(double phi) { return std::cos(3.0 * phi) + 0.5 * std::sin(36.0 * phi); }

TEST(AngleAverage, RecoversALockedPatternUnderFluctuatingSpeedEitherDirection) {
  // Linear interpolation in angle errs by ≤ h²·max|g''|/8, h = the largest angle step between
  // samples ((ω + 0.72)/fs = 2.83e-3 rad), max|g''| = 9 + 0.5·36² = 657: 6.6e-4.
  const double h = (kOmega + kWobble * kTwoPi * kWobbleHz) / kFs;
  const double bound = h * h * 657.0 / 8.0;
  for (const double direction : {1.0, -1.0}) {
    const std::vector<double> t = times(10.5);
    std::vector<double> angle(t.size()), signal(t.size());
    for (std::size_t i = 0; i < t.size(); ++i) {
      angle[i] = body_angle(t[i], direction);
      signal[i] = pattern(angle[i]);
    }
    const AngleAverage avg = angle_synchronous_average(signal, angle, 512);
    EXPECT_EQ(avg.revolutions, 10);  // 10.5 turns hold 10 whole ones
    ASSERT_EQ(avg.mean.size(), 512u);
    double worst = 0.0;
    for (std::size_t j = 0; j < avg.mean.size(); ++j) worst = std::max(worst, std::abs(avg.mean[j] - pattern(avg.angle_rad[j])));
    EXPECT_LE(worst, bound) << "direction " << direction;
  }
}

// A contact-force-like signal: one sin² bump per tooth window, tooth `weak` carrying `factor`.
double tooth_force(double phi, double tooth0_rad, int weak, double factor) {
  const double pitch = kTwoPi / kTeeth;
  double rel = std::fmod(phi - tooth0_rad, kTwoPi);
  if (rel < 0) rel += kTwoPi;
  const int tooth = static_cast<int>(rel / pitch);
  const double u = rel / pitch - tooth;
  const double bump = std::pow(std::sin(std::numbers::pi * u), 2);
  return 100.0 * bump * (tooth == weak ? factor : 1.0);  // N
}

TEST(ToothStatistics, FindsExactlyThePlantedTooth) {
  // Tooth 7 carries 85 % of the others' load; noise σ = 2 N on 100 N peaks. The planted tooth's
  // in-mesh mean is ≈ 9.5 N below the others', whose means scatter by ≈ 0.1 N: z ≈ −100. Each
  // healthy tooth's reference set holds tooth 7, whose offset inflates the spread to ≈ 1.6 N, so
  // healthy |z| stays below 0.3. Threshold 3.5 (the default): a wide margin both ways.
  constexpr double kTooth0 = 0.3;  // rad
  const std::vector<double> t = times(10.5);
  const std::vector<double> noise = test::white_noise(t.size(), 2.0, 5);
  std::vector<double> angle(t.size()), force(t.size());
  for (std::size_t i = 0; i < t.size(); ++i) {
    angle[i] = body_angle(t[i], -1.0);  // the paper's planets turn backwards relative to the carrier
    force[i] = tooth_force(angle[i], kTooth0, 7, 0.85) + noise[i];
  }
  const AngleAverage avg = angle_synchronous_average(force, angle, 36 * 32);
  ToothStatisticsOptions o;
  o.teeth = kTeeth;
  o.tooth0_start_rad = kTooth0;
  o.in_mesh_threshold = 10.0;  // N: count only the loaded part of each window
  const ToothStatistics s = tooth_statistics(avg, o);
  EXPECT_EQ(s.faulty_teeth, std::vector<int>{7});
  for (const ToothStatistic& tooth : s.teeth) {
    if (tooth.tooth == 7)
      EXPECT_LT(tooth.z_score, -o.z_threshold);
    else
      EXPECT_LT(std::abs(tooth.z_score), o.z_threshold) << "tooth " << tooth.tooth;
    EXPECT_GT(tooth.samples, 16) << "tooth " << tooth.tooth;  // of 32 per window, most in mesh
  }
}

TEST(ToothStatistics, ThresholdAboveEverySampleIsRejected) {
  const std::vector<double> t = times(2.0);
  std::vector<double> angle(t.size()), force(t.size());
  for (std::size_t i = 0; i < t.size(); ++i) {
    angle[i] = body_angle(t[i], 1.0);
    force[i] = tooth_force(angle[i], 0.0, -1, 1.0);
  }
  ToothStatisticsOptions o;
  o.teeth = kTeeth;
  o.in_mesh_threshold = 1000.0;  // N: above the 100 N peaks
  EXPECT_THROW(tooth_statistics(angle_synchronous_average(force, angle, 1024), o), InputError);
}

TEST(AngleAverage, BadInputIsRejected) {
  EXPECT_THROW(angle_synchronous_average({1, 2, 3}, {0, 1}, 64), InputError);  // lengths
  EXPECT_THROW(angle_synchronous_average({1, 2, 3, 4}, {0, 7, 3, 14}, 64), InputError);  // not monotone
  EXPECT_THROW(angle_synchronous_average({1, 2, 3}, {0, 1, 2}, 64), InputError);  // < 1 turn
}

}  // namespace test_angle_average
}  // namespace gearsim
