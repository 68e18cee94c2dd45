#include "contact/stiffness_table.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/errors.hpp"

namespace gearsim::contact {

Check check_stiffness_table(const StiffnessTable& t) {
  std::ostringstream msg;
  int row = -1;
  if (t.radius_m.size() != t.stiffness_N_per_m_per_m.size())
    msg << t.radius_m.size() << " radii but " << t.stiffness_N_per_m_per_m.size() << " stiffnesses";
  else if (t.radius_m.size() < 2)
    msg << "expected at least 2 rows, got " << t.radius_m.size();
  else
    for (std::size_t i = 0; i < t.radius_m.size(); ++i) {
      if (!(t.radius_m[i] > 0) || !std::isfinite(t.radius_m[i])) {
        msg << "radius " << t.radius_m[i] << " m is not a positive number";
        row = static_cast<int>(i);
        break;
      }
      if (i > 0 && !(t.radius_m[i] > t.radius_m[i - 1])) {
        msg << "radius " << t.radius_m[i] << " m is not above the previous row's " << t.radius_m[i - 1]
            << " m (radii must increase strictly)";
        row = static_cast<int>(i);
        break;
      }
      if (!(t.stiffness_N_per_m_per_m[i] > 0) || !std::isfinite(t.stiffness_N_per_m_per_m[i])) {
        msg << "stiffness " << t.stiffness_N_per_m_per_m[i] << " N/m per m is not positive";
        row = static_cast<int>(i);
        break;
      }
    }
  if (msg.str().empty()) return {};
  return Refusal{msg.str(), row};
}

StiffnessLookup stiffness_at(const StiffnessTable& t, double r) {
  GEARSIM_CHECK(t.radius_m.size() >= 2 && t.radius_m.size() == t.stiffness_N_per_m_per_m.size(),
                "a stiffness table is validated before use");
  const std::vector<double>& x = t.radius_m;
  const std::vector<double>& k = t.stiffness_N_per_m_per_m;
  const bool outside = r < x.front() || r > x.back();
  if (r <= x.front()) return {k.front(), outside};
  if (r >= x.back()) return {k.back(), outside};
  // First row above r; the segment [i − 1, i] holds it.
  const std::size_t i = static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), r) - x.begin());
  const double s = (r - x[i - 1]) / (x[i] - x[i - 1]);
  return {k[i - 1] + s * (k[i] - k[i - 1]), false};
}

}  // namespace gearsim::contact
