// A scenario's scheduled events against the run's duration: each impulse (an impact hammer's
// pulse, physics::ImpulseDef) must start and end within [0, duration_s], or part of it would be
// silently lost. Checked when a scenario is read, and again when --duration shortens a run after
// loading. Not the ramps of motors and loads: a run may end during a ramp, and says so in its logs.
#pragma once

#include <string>

#include "physics/scenario.hpp"

namespace gearsim::input {

// "" when the event from at_s to at_s + length_s (s) lies within [0, duration_s], else why not
// ("the pulse from 9999 s to 9999.001 s ends after the run's end at 0.1 s").
std::string event_outside_run(double at_s, double length_s, double duration_s);

// Every scheduled event of `scenario` against scenario.duration_s. InputError naming the scenario
// file, the event's key (impulses[2].at_s), the event and `duration_from` (what set the duration,
// e.g. "--duration 0.1") otherwise.
void check_events_within_duration(const physics::Scenario& scenario, const std::string& duration_from);

}  // namespace gearsim::input
