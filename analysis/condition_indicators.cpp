#include "analysis/condition_indicators.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <string>

#include "analysis/fft.hpp"
#include "core/errors.hpp"

namespace gearsim {
namespace {

struct Moments {
  double mean = 0, m2 = 0, m4 = 0, m6 = 0;  // central sums Σ(x − x̄)^p
  double n = 0;
};

Moments moments(const std::vector<double>& x) {
  if (x.size() < 2) throw InputError("condition indicators: expected at least 2 samples, got " + std::to_string(x.size()));
  Moments m;
  m.n = static_cast<double>(x.size());
  for (double v : x) {
    if (!std::isfinite(v)) throw InputError("condition indicators: a sample is not finite");
    m.mean += v;
  }
  m.mean /= m.n;
  for (double v : x) {
    const double d = v - m.mean, d2 = d * d;
    m.m2 += d2, m.m4 += d2 * d2, m.m6 += d2 * d2 * d2;
  }
  if (!(m.m2 > 0)) throw InputError("condition indicators: the record is constant (no variance)");
  return m;
}

// x with only the orders `keep` says (by order index) kept: its DFT masked, transformed back.
template <class Keep>
std::vector<double> orders_only(std::vector<std::complex<double>> X, std::size_t n, Keep keep) {
  X[0] = 0;  // the mean: never kept
  for (std::size_t k = 1; k < X.size(); ++k)
    if (!keep(static_cast<int>(k))) X[k] = 0;
  return real_idft(X, n);
}

double rms_of(const std::vector<double>& x) {
  double s = 0;
  for (double v : x) s += v * v;
  return std::sqrt(s / static_cast<double>(x.size()));
}

}  // namespace

double order_amplitude(const std::vector<double>& x, int order) {
  if (order < 0 || static_cast<std::size_t>(order) > x.size() / 2)
    throw InputError("order " + std::to_string(order) + " is not between 0 and half the " + std::to_string(x.size()) + " samples");
  const std::vector<std::complex<double>> X = real_dft(x, x.size());
  const double n = static_cast<double>(x.size());
  const bool single = order == 0 || (x.size() % 2 == 0 && static_cast<std::size_t>(order) == x.size() / 2);
  return (single ? 1.0 : 2.0) * std::abs(X[static_cast<std::size_t>(order)]) / n;
}

TsaSignals tsa_signals(const std::vector<double>& tsa, int teeth) {
  if (teeth < 1) throw InputError("condition indicators: a gear needs at least 1 tooth");
  if (tsa.size() < 4 * static_cast<std::size_t>(teeth))
    throw InputError("condition indicators: " + std::to_string(tsa.size()) + " samples per revolution for " + std::to_string(teeth) +
                     " teeth; expected at least 4 per tooth");
  const std::size_t n = tsa.size();
  const std::vector<std::complex<double>> X = real_dft(tsa, n);
  auto mesh = [&](int k) { return k % teeth == 0; };
  auto sideband = [&](int k) { return (k + 1) % teeth == 0 || (k - 1) % teeth == 0; };
  auto shaft = [&](int k) { return k == 1 || k == 2; };
  TsaSignals s;
  s.regular = orders_only(X, n, [&](int k) { return mesh(k) || sideband(k) || shaft(k); });
  s.residual = orders_only(X, n, [&](int k) { return !(mesh(k) || shaft(k)); });
  s.difference = orders_only(X, n, [&](int k) { return !(mesh(k) || sideband(k) || shaft(k)); });
  s.mesh = orders_only(X, n, mesh);
  return s;
}

double rms_about_mean(const std::vector<double>& x) {
  const Moments m = moments(x);
  return std::sqrt(m.m2 / m.n);
}

double crest_factor(const std::vector<double>& x) {
  const Moments m = moments(x);
  double peak = 0;
  for (double v : x) peak = std::max(peak, std::abs(v - m.mean));
  return peak / std::sqrt(m.m2 / m.n);
}

double kurtosis(const std::vector<double>& x) {
  const Moments m = moments(x);
  return m.n * m.m4 / (m.m2 * m.m2);
}

double sixth_moment(const std::vector<double>& x) {
  const Moments m = moments(x);
  return m.n * m.n * m.m6 / (m.m2 * m.m2 * m.m2);
}

ConditionIndicators condition_indicators(const std::vector<double>& tsa, int teeth, const std::vector<std::vector<double>>& history) {
  const TsaSignals s = tsa_signals(tsa, teeth);
  ConditionIndicators c;
  c.rms = rms_about_mean(tsa);
  c.crest_factor = crest_factor(tsa);
  c.kurtosis = kurtosis(tsa);
  double mesh_sum = 0;
  for (std::size_t k = static_cast<std::size_t>(teeth); k <= tsa.size() / 2; k += static_cast<std::size_t>(teeth))
    mesh_sum += order_amplitude(tsa, static_cast<int>(k));
  const auto [lo, hi] = std::minmax_element(tsa.begin(), tsa.end());
  c.fm0 = mesh_sum > 0 ? (*hi - *lo) / mesh_sum : std::numeric_limits<double>::infinity();
  // A difference signal without variance (a TSA of mesh orders, sidebands and shaft orders only)
  // has no shape: FM4, M6A and ER's numerator are left NaN / 0 rather than dividing by zero.
  const double d_rms = rms_of(s.difference);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double scale = std::max(c.rms, 1e-300);
  const bool shaped = d_rms > 1e-12 * scale;
  c.fm4 = shaped ? kurtosis(s.difference) : nan;
  c.m6a = shaped ? sixth_moment(s.difference) : nan;
  // NA4: this residual's fourth moment over the mean variance of all records so far (this one too).
  if (!(rms_of(s.residual) > 1e-12 * scale)) {
    c.na4 = nan;
    c.er = 0;
    return c;
  }
  const Moments now = moments(s.residual);
  double mean_variance = now.m2 / now.n;
  for (const std::vector<double>& r : history) {
    const Moments h = moments(r);
    mean_variance += h.m2 / h.n;
  }
  mean_variance /= static_cast<double>(history.size() + 1);
  c.na4 = (now.m4 / now.n) / (mean_variance * mean_variance);
  const double mesh_rms = rms_of(s.mesh);
  c.er = mesh_rms > 0 ? d_rms / mesh_rms : std::numeric_limits<double>::infinity();
  return c;
}

}  // namespace gearsim
