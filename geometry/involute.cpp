#include "geometry/involute.hpp"

#include "geometry/errors.hpp"

namespace gearsim {

double inverse_involute(double value) {
  GEARSIM_CHECK(value >= 0.0, "inverse_involute needs a non-negative value");
  if (value == 0.0) return 0.0;
  // Start from the series inversion α ≈ (3v)^(1/3) − 2v/5, good to a few % for v < 1.
  double a = std::cbrt(3.0 * value) - 0.4 * value;
  if (a >= 1.5) a = 1.5;
  for (int i = 0; i < 60; ++i) {
    const double t = std::tan(a);
    const double f = t - a - value;
    const double df = t * t;  // d(tan a − a)/da = tan² a
    const double step = f / df;
    a -= step;
    if (std::abs(step) < 1e-15 * (1.0 + std::abs(a))) break;
  }
  return a;
}

}  // namespace gearsim
