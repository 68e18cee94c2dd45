// The bounds every number from an input file or the command line is checked against before
// anything is allocated or run from it, each with its unit and why. A value outside is refused
// naming file:line:key (or the option) and the bound; NaN and infinity are always refused.
// Bounds are sanity limits far beyond any real gearbox run, not physics: the physical bounds of
// a running simulation are sim/run_bounds.hpp. Not a schema: each reader applies the limit
// of the key it reads.
#pragma once

#include <CLI/CLI.hpp>

#include <cstddef>
#include <string>

#include "input/yaml_reader.hpp"

namespace gearsim::input {

// A closed interval [min, max] in `unit`, or (min, max] when min_open.
struct Limit {
  double min;
  double max;
  bool min_open;
  const char* unit;  // "s", "Hz", "" for counts and factors
  const char* what;  // the message's noun: "a duration"
};

namespace limits {

// Scenario and gear-set files are a few kB (the largest in assets/ is 5 kB); yaml-cpp holds about
// 30× the text in memory (a 50 MB file peaked at 1.6 GB), so 4 MiB stays near 130 MB.
constexpr std::size_t kMaxYamlBytes = 4u << 20;
// Values in one YAML file, aliases counted each time they are met: a file of 4 MiB holds at most
// ~1e6 values; more means aliases multiplying a list ("billion laughs").
constexpr std::size_t kMaxYamlValues = 1'000'000;

// Simulated time, s: the paper's set costs ~4 s wall per simulated second at dt 2e-5 s, so 1e4 s
// is about 11 h and 5e8 steps; more is a typo (--duration 1e300 gave 0 steps).
constexpr Limit kDuration_s{0, 1e4, true, "s", "a duration"};
// Time step, s: below 1e-7 s a simulated second takes ~1e3 times the paper run's wall time; above
// 1e-2 s not even the mesh frequency of a slow train (~100 Hz) is resolved.
constexpr Limit kTimeStep_s{1e-7, 1e-2, false, "s", "a time step"};
// Constraint solver iterations per step: 2000× the default 50; each is a sweep over every constraint.
constexpr Limit kSolverIterations{1, 1e5, false, "", "a number of solver iterations"};
// θ of the multibody engine's θ-method: below ½ it is unstable for stiff springs, 1 is implicit Euler.
constexpr Limit kSolverTheta{0.5, 1, false, "", "a θ-method weight"};
// Motor and load ramps, s: no longer than the longest run (kDuration_s).
constexpr Limit kRampTime_s{0, 1e4, false, "s", "a ramp time"};
// Render slow motion: 1000× shows 1 ms of the run as 1 s of video; frames = duration·fps·slowmo.
constexpr Limit kSlowMotion{0, 1000, true, "", "a slow-motion factor"};
// Times within a run (render and analysis windows), s: within the longest run.
constexpr Limit kRunTime_s{0, 1e4, false, "s", "a time"};
// Planets of a planetary train: each is a body, a hinge and two meshes allocated before the
// assembly check; 64 equally spaced planets already need over 200 teeth on the sun.
constexpr Limit kPlanets{1, 64, false, "", "a number of planets"};
// Teeth of a gear or of a mesh's tooth layout: 3 is the fewest an involute gear can have; a
// 1000-tooth outline at the default 0.5 µm chordal deviation is ~1e6 points, beyond any gearbox.
constexpr Limit kTeeth{3, 1000, false, "", "a number of teeth"};
// Chordal deviation of gear outlines, m: below 1 nm the outline is millions of points per tooth;
// above 0.1 mm a 1 mm module tooth (2.25 mm high) is a few segments and its flanks are lost.
constexpr Limit kChordalDeviation_m{1e-9, 1e-4, false, "m", "a chordal deviation"};

// Cases of one parameter sweep (grid product or list): each is a run folder and a process; 1e5
// runs of the shortest useful case (~1 s) are a day on 2 cores, more is a typo in a grid.
constexpr std::size_t kMaxSweepCases = 100'000;
// Values of one grid axis ({from, to, steps}): as many as a sweep may have cases.
constexpr Limit kSweepSteps{2, 1e5, false, "", "a number of grid steps"};

}  // namespace limits

// True for a finite value inside the limit.
bool within(double value, const Limit& limit);
// "expected a duration in (0, 10000] s, got 1e+300".
std::string limit_message(const Limit& limit, double value);

// m[key] as a number within `limit`, else m.fail(key, limit_message(…)).
double number_within(const YamlMap& m, const std::string& key, const Limit& limit);
// The same with a fallback when the key is absent (the fallback is not checked).
double number_within_or(const YamlMap& m, const std::string& key, double fallback, const Limit& limit);
// m[key] as an integer within `limit` (checked before any narrowing).
int integer_within(const YamlMap& m, const std::string& key, const Limit& limit);
int integer_within_or(const YamlMap& m, const std::string& key, int fallback, const Limit& limit);

// A CLI11 check of an option's value against `limit` (NaN, inf and text refused).
CLI::Validator cli_within(const Limit& limit);

}  // namespace gearsim::input
