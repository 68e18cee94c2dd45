#include "fe/closing_turn.hpp"

#include <cmath>

#include "core/errors.hpp"
#include "fe/constants.hpp"

namespace gearsim::fe {

double closing_turn(const std::function<bool(double)>& touching, double sense, const std::string& who) {
  const bool start = touching(0.0);
  // Step until the state changes: lo keeps the starting state, hi the other.
  double lo = 0, hi = 0;
  for (double d = kClosingStep_rad; d <= kMaxClosingTurn_rad + 1e-15; d += kClosingStep_rad) {
    const double delta = start ? -d * sense : d * sense;
    if (touching(delta) != start) {
      hi = delta;
      break;
    }
    lo = delta;
  }
  if (hi == 0)
    throw InputError(who + ": no touching position within " + std::to_string(kMaxClosingTurn_rad) + " rad (the gears do not mesh)");
  // Bisection; return the touching side's bound.
  while (std::abs(hi - lo) > kClosingTolerance_rad) {
    const double mid = 0.5 * (lo + hi);
    (touching(mid) == start ? lo : hi) = mid;
  }
  return start ? lo : hi;
}

}  // namespace gearsim::fe
