#include "analysis/ringing.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

#include "analysis/constants.hpp"
#include "core/errors.hpp"

namespace gearsim {
namespace {

std::string ringing_number(double v) {
  std::ostringstream out;
  out.precision(10);
  out << v;
  return out.str();
}

double ringing_dot(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
  return s;
}

}  // namespace

RingingEstimate estimate_ringing(const std::vector<double>& x, double sample_rate_hz) {
  if (!std::isfinite(sample_rate_hz) || sample_rate_hz <= 0.0)
    throw InputError("ringing: sample rate must be a positive number of Hz, got " + ringing_number(sample_rate_hz));
  if (x.size() < 8) throw InputError("ringing: expected at least 8 samples, got " + std::to_string(x.size()));
  double mean = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    if (!std::isfinite(x[k])) throw InputError("ringing: sample " + std::to_string(k) + " is not finite (" + ringing_number(x[k]) + ")");
    mean += x[k];
  }
  mean /= static_cast<double>(x.size());
  double spread = 0.0;  // RMS about the mean
  for (const double v : x) spread += (v - mean) * (v - mean);
  spread = std::sqrt(spread / static_cast<double>(x.size()));
  if (!(spread > 0.0)) throw InputError("ringing: the record is constant (" + ringing_number(mean) + ")");

  // Least squares for x_n − mean = c0 + c1·(x_{n−1} − mean) + c2·(x_{n−2} − mean), n = 2 … N−1, by
  // modified Gram–Schmidt (accurate to the matrix's condition, not its square).
  const std::size_t rows = x.size() - 2;
  std::array<std::vector<double>, 3> q;
  q[0].assign(rows, 1.0);
  q[1].resize(rows);
  q[2].resize(rows);
  std::vector<double> b(rows);
  for (std::size_t i = 0; i < rows; ++i) {
    q[1][i] = x[i + 1] - mean;
    q[2][i] = x[i] - mean;
    b[i] = x[i + 2] - mean;
  }
  std::array<std::array<double, 3>, 3> r{};
  std::array<double, 3> qb{};
  for (std::size_t j = 0; j < 3; ++j) {
    const double before = std::sqrt(ringing_dot(q[j], q[j]));
    for (std::size_t i = 0; i < j; ++i) {
      r[i][j] = ringing_dot(q[i], q[j]);
      for (std::size_t n = 0; n < rows; ++n) q[j][n] -= r[i][j] * q[i][n];
    }
    r[j][j] = std::sqrt(ringing_dot(q[j], q[j]));
    // A column (nearly) in the span of the others: the record holds fewer than two modes' worth.
    if (!(r[j][j] > analysis_constants::kRingingRankTolerance * before))
      throw InputError(
          "ringing: the record is not an oscillation (its samples follow a first-order "
          "recurrence, e.g. a plain exponential decay)");
    for (double& v : q[j]) v /= r[j][j];
    qb[j] = ringing_dot(q[j], b);
    for (std::size_t n = 0; n < rows; ++n) b[n] -= qb[j] * q[j][n];
  }
  std::array<double, 3> c{};
  for (std::size_t j = 3; j-- > 0;) {
    double s = qb[j];
    for (std::size_t i = j + 1; i < 3; ++i) s -= r[j][i] * c[i];
    c[j] = s / r[j][j];
  }
  RingingEstimate e;
  e.relative_residual = std::sqrt(ringing_dot(b, b) / static_cast<double>(rows)) / spread;

  // Poles of z² − c1·z − c2: complex r·e^{±iθ} when c2 < 0 and |c1| < 2r.
  const double c1 = c[1], c2 = c[2];
  const double radius = c2 < 0.0 ? std::sqrt(-c2) : 0.0;
  if (!(c2 < 0.0) || !(std::abs(c1) < 2.0 * radius))
    throw InputError("ringing: the record's best two-pole fit does not oscillate (real poles: c1 = " + ringing_number(c1) +
                     ", c2 = " + ringing_number(c2) + ")");
  const double theta = std::acos(c1 / (2.0 * radius));  // rad per sample, (0, π)
  const double wd = theta * sample_rate_hz;  // rad/s
  e.frequency_hz = wd / (2.0 * std::numbers::pi);
  e.decay_rate_per_s = -std::log(radius) * sample_rate_hz;
  e.damping_ratio = e.decay_rate_per_s / std::hypot(wd, e.decay_rate_per_s);
  return e;
}

}  // namespace gearsim
