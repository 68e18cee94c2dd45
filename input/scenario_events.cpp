#include "input/scenario_events.hpp"

#include <sstream>

#include "core/errors.hpp"

namespace gearsim::input {
namespace {

// Slack on the end, relative to the duration: a pulse written to end exactly at the run's end
// (at_s + duration_s in decimal) may exceed it by a rounding.
constexpr double kPulseEndSlack = 1e-12;

}  // namespace

std::string event_outside_run(double at_s, double length_s, double duration_s) {
  const double end_s = at_s + length_s;
  if (at_s >= 0 && end_s <= duration_s * (1 + kPulseEndSlack)) return "";
  std::ostringstream why;
  why.precision(9);
  why << "the pulse from " << at_s << " s to " << end_s << " s ";
  if (at_s < 0)
    why << "starts before the run's start at 0 s";
  else
    why << "ends after the run's end at " << duration_s << " s";
  why << ": expected a pulse within [0, " << duration_s << "] s (the run would skip " << (at_s >= duration_s ? "it" : "its end") << ")";
  return why.str();
}

void check_events_within_duration(const physics::Scenario& s, const std::string& duration_from) {
  for (std::size_t i = 0; i < s.impulses.size(); ++i) {
    const physics::ImpulseDef& p = s.impulses[i];
    if (const std::string why = event_outside_run(p.at_s, p.duration_s, s.duration_s); !why.empty())
      throw InputError(s.source.string() + ": impulses[" + std::to_string(i) + "].at_s: " + why + " (duration set by " + duration_from +
                       ")");
  }
}

}  // namespace gearsim::input
