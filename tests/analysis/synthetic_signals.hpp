// Synthetic test signals for the analysis tests: tones, modulated mesh signals, white noise.
// Closed forms only, so every expected value in a test comes from the formula, not from the code.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

namespace gearsim::test {

inline constexpr double kTwoPi = 2.0 * std::numbers::pi;

// x_n = a·cos(2π·f·n/fs + phase), n = 0 … count−1.
inline std::vector<double> tone(std::size_t count, double fs_hz, double f_hz, double a, double phase_rad = 0) {
  std::vector<double> x(count);
  for (std::size_t n = 0; n < count; ++n) x[n] = a * std::cos(kTwoPi * f_hz * static_cast<double>(n) / fs_hz + phase_rad);
  return x;
}

// Gaussian white noise of standard deviation sigma, from a fixed seed (same bits every run).
inline std::vector<double> white_noise(std::size_t count, double sigma, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal(0.0, sigma);
  std::vector<double> x(count);
  for (double& v : x) v = normal(rng);
  return x;
}

inline void add(std::vector<double>& x, const std::vector<double>& y) {
  for (std::size_t i = 0; i < x.size(); ++i) x[i] += y[i];
}

}  // namespace gearsim::test
