#include "geometry/involute.hpp"

#include <numbers>

#include "core/errors.hpp"

namespace gearsim {

double inverse_involute(double value) {
  GEARSIM_CHECK(value >= 0.0 && std::isfinite(value), "inverse_involute needs a finite value ≥ 0");
  if (value == 0.0) return 0.0;
  // inv is increasing on [0, π/2): keep a bracket [lo, hi] and take Newton steps that stay in it,
  // bisecting otherwise. Converges to machine precision in a handful of steps.
  double lo = 0.0, hi = std::numbers::pi / 2;
  double a = std::min(std::cbrt(3.0 * value), 1.5);  // inv α ≈ α³/3 for small α
  for (int i = 0; i < 200; ++i) {
    const double f = involute(a) - value;
    if (f > 0)
      hi = a;
    else
      lo = a;
    const double t = std::tan(a);
    double next = a - f / (t * t);  // d(inv α)/dα = tan² α
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - a) <= 1e-16 * a) return next;
    a = next;
  }
  return a;
}

}  // namespace gearsim
