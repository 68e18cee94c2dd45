#include "analysis/planet_separation.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "core/errors.hpp"

namespace gearsim {

double planet_pass_hann(double delta_rad, double width_rad) {
  const double delta = std::remainder(delta_rad, 2 * std::numbers::pi);
  return std::abs(delta) < width_rad / 2 ? 0.5 * (1 + std::cos(2 * std::numbers::pi * delta / width_rad)) : 0.0;
}

namespace {
// Means from sums, the coverage, and unseen bins interpolated.
void finish_average(PlanetSeparatedAverage& a);

// The samples taken while a planet at `position` passes the sensor, weighted by its window and
// summed into the grid bin of `turn` (the turn the average is taken over); passes counted.
void add_passes(PlanetSeparatedAverage& a, const std::vector<double>& x, const std::vector<double>& position,
                const std::vector<double>& turn, double sensor, double width) {
  constexpr double kTurn = 2 * std::numbers::pi;
  const auto n = static_cast<std::size_t>(a.samples_per_revolution);
  bool inside = false;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double w = planet_pass_hann(position[i] - sensor, width);
    if (w > 0 && !inside) a.passes += 1;
    inside = w > 0;
    if (w == 0) continue;
    double t = std::fmod(turn[i], kTurn);
    if (t < 0) t += kTurn;
    const auto j = static_cast<std::size_t>(std::lround(t / kTurn * static_cast<double>(n))) % n;
    a.mean[j] += w * x[i];
    a.weight[j] += w;
  }
}
}  // namespace

PlanetSeparatedAverage planet_separated_average(const std::vector<double>& x, const std::vector<double>& position,
                                                const std::vector<double>& spin, double sensor, double width, int n) {
  constexpr double kTurn = 2 * std::numbers::pi;
  if (x.size() != position.size() || x.size() != spin.size())
    throw InputError("planet separation: signal, position and spin must be sampled together (" + std::to_string(x.size()) + ", " +
                     std::to_string(position.size()) + ", " + std::to_string(spin.size()) + " samples)");
  if (x.size() < 2) throw InputError("planet separation: expected at least 2 samples");
  if (!(width > 0 && width <= kTurn + 1e-12)) throw InputError("planet separation: the window width must lie in (0, 2π]");
  if (n < 4) throw InputError("planet separation: expected at least 4 samples per revolution");
  PlanetSeparatedAverage a;
  a.samples_per_revolution = n;
  a.mean.assign(static_cast<std::size_t>(n), 0.0);
  a.weight.assign(static_cast<std::size_t>(n), 0.0);
  add_passes(a, x, position, spin, sensor, width);
  if (a.passes == 0) throw InputError("planet separation: the planet never passes the sensor in this record");
  finish_average(a);
  return a;
}

namespace {
void finish_average(PlanetSeparatedAverage& a) {
  const int n = a.samples_per_revolution;
  int seen = 0;
  for (std::size_t j = 0; j < a.mean.size(); ++j)
    if (a.weight[j] > 0) a.mean[j] /= a.weight[j], ++seen;
  a.coverage = static_cast<double>(seen) / n;
  if (seen == 0) return;
  // Bins never seen: linear between the nearest seen bins on either side (around the circle).
  const auto N = static_cast<std::size_t>(n);
  for (std::size_t j = 0; j < N; ++j) {
    if (a.weight[j] > 0) continue;
    std::size_t lo = j, hi = j, dl = 0, dh = 0;
    while (a.weight[lo] <= 0) lo = (lo + N - 1) % N, ++dl;
    while (a.weight[hi] <= 0) hi = (hi + 1) % N, ++dh;
    a.mean[j] = (a.mean[lo] * static_cast<double>(dh) + a.mean[hi] * static_cast<double>(dl)) / static_cast<double>(dl + dh);
  }
}
}  // namespace

PlanetSeparatedAverage sun_separated_average(const std::vector<double>& x, const std::vector<std::vector<double>>& position,
                                             const std::vector<double>& offset, const std::vector<double>& sun, double sensor, double width,
                                             int n) {
  constexpr double kTurn = 2 * std::numbers::pi;
  if (position.size() != offset.size() || position.empty()) throw InputError("sun separation: one position and one offset per planet");
  for (const std::vector<double>& p : position)
    if (p.size() != x.size()) throw InputError("sun separation: every planet's position must be sampled with the signal");
  if (sun.size() != x.size() || x.size() < 2) throw InputError("sun separation: the sun's turn must be sampled with the signal");
  if (!(width > 0 && width <= kTurn + 1e-12)) throw InputError("sun separation: the window width must lie in (0, 2π]");
  if (n < 4) throw InputError("sun separation: expected at least 4 samples per revolution");
  PlanetSeparatedAverage a;
  a.samples_per_revolution = n;
  a.mean.assign(static_cast<std::size_t>(n), 0.0);
  a.weight.assign(static_cast<std::size_t>(n), 0.0);
  std::vector<double> turn(x.size());
  for (std::size_t p = 0; p < position.size(); ++p) {
    // The sun tooth that meets planet p: the sun's turn relative to the carrier less p's place.
    for (std::size_t i = 0; i < x.size(); ++i) turn[i] = sun[i] - offset[p];
    add_passes(a, x, position[p], turn, sensor, width);
  }
  if (a.passes == 0) throw InputError("sun separation: no planet passes the sensor in this record");
  finish_average(a);
  return a;
}

}  // namespace gearsim
