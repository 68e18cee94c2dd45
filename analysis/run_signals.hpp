// What the analysis of a finished run reads, as plain typed values: the signals the run logged
// (the output-rate time base, each gear pair's identity and normal force, the transmission error,
// body angles, and the per-step tooth contacts when the run kept them) and the gear train they
// came from (its characteristic frequencies, its planets, the gears whose teeth are counted).
// Not a reader: app/ fills these from a run folder; the analysis never sees a file, a column name
// or a scenario.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "analysis/characteristic_frequencies.hpp"
#include "analysis/transmission_error.hpp"

namespace gearsim {

// A gear pair: its two bodies, in the order the world lists them (the contact log's tooth_a is a
// tooth of `a`). An identity to compare, never a name to parse.
struct PairId {
  std::string a, b;
  bool operator==(const PairId&) const = default;
  // True for {x, y} and {y, x}: the same two bodies in either order.
  bool same_bodies(const std::string& x, const std::string& y) const { return (a == x && b == y) || (a == y && b == x); }
};

// "a–b", for messages.
inline std::string pair_label(const PairId& p) { return p.a + "–" + p.b; }

// One gear pair's normal contact force, summed over its tooth contacts, at each output sample, N.
struct PairForce {
  PairId pair;
  std::vector<double> force_N;  // at each sample time; anti-aliased when the run filtered it
  // The same force point-sampled at each time (exactly 0 when no tooth pair touched): what the
  // share of samples without contact is counted on. Empty: force_N is the point sample.
  std::vector<double> point_force_N;
};

// A body's rotation angle at each output sample, rad, unwrapped (a planet's: relative to its
// carrier, as the run logs it).
struct BodyAngle {
  std::string body;
  std::vector<double> angle_rad;
};

// The per-step tooth contacts of a run: one row per tooth-pair contact per step.
struct ToothContactLog {
  std::vector<PairId> pairs;  // the gear pairs; pair[c] indexes this
  std::vector<double> time_s;  // the step's time, s
  std::vector<std::int64_t> pair, tooth_a, tooth_b;  // tooth_a: a tooth of pairs[pair[c]].a
  std::vector<double> normal_impulse_N_s;  // normal impulse over the step, N·s
  double time_step_s = 0;  // the run's step, s
};

// A housing sensor's record (sensors.csv) and where it sits.
struct SensorSignal {
  std::string name;
  double angle_rad = 0;  // about the set's centre, world
  double window_width_rad = 0;  // its planet-pass window (the model's)
  double resonance_hz = 0;  // the housing mode it rings at (0: unknown): the envelope band's centre
  std::vector<double> time_s;
  std::vector<double> acceleration_m_s2;
};

struct RunSignals {
  std::vector<double> time_s;  // output-rate sample instants, s (uniform from from_s on)
  std::vector<PairForce> pair_forces;  // every gear pair, in the world's order, sampled at time_s
  // θ_in − i·θ_out as the run logged it, sampled at time_s; nothing when the run has no
  // transmission (transmission_error_series builds it).
  std::optional<TransmissionError> te;
  std::vector<BodyAngle> angles;  // sampled at time_s: at least the planets and the counted gears
  std::optional<ToothContactLog> tooth_contacts;  // nothing: the run kept no per-step log
  std::vector<SensorSignal> sensors;  // the run's housing sensors (at their own rate)
  double from_s = 0;  // start of the analysed window, s: samples with time_s ≥ from_s are analysed
};

// A planet, as its angle-synchronous average needs it.
struct PlanetGear {
  std::string body;
  int teeth = 0;
  // Where the sun lies seen from the planet at t = 0 in the carrier frame, less the planet's
  // tooth-0 angle, rad: tooth k faces the sun when the planet's relative angle is this − k·2π/z.
  double sun_direction_rad = 0;
  // Where its centre sits about the set's centre at t = 0 (world angle, rad): with the carrier's
  // turn, where it is when (a sensor's planet-pass window).
  double position0_rad = 0;
  std::string sun{};  // the sun it meshes with ("": TrainDescription::sun)
};

// A gear whose per-tooth loads are taken from the tooth-contact log.
struct CountedGear {
  std::string body;
  int teeth = 0;
};

// The gear train of the run, as the analysis needs it.
struct TrainDescription {
  GearTrainFrequencies frequencies;  // characteristic frequencies; mesh_hz the fundamental f_m
  // A planetary set: its force spectra get the planet local-fault family (key "planet_fault"
  // must be among the frequencies) and its planets a synchronous average.
  bool planetary = false;
  std::string sun;  // planetary: the sun's body
  std::vector<PlanetGear> planets;  // planetary: every planet
  std::string carrier;  // planetary: the carrier's body (its angle is logged)
  // planetary: the planets mesh in phase (z_s/N whole): at every instant each is at the same
  // point of its own mesh cycle, so a fixed sensor cannot tell one planet's events from another's.
  bool planets_in_phase = false;
  int sun_teeth = 0;  // planetary: for the sun's separated average
  // Gears whose per-tooth loads are reported (the planets of a set; the driven gear of a pair),
  // on whichever side of a logged pair they are.
  std::vector<CountedGear> counted_gears;
  // Which flank of gear a carried each pair's load ("ccw"/"cw"; none: unknown), and whether b is a
  // ring (inside which the flanks' names swap: a's ccw flank touches a ring's cw flank).
  struct LoadedFlank {
    PairId pair;
    std::string flank_of_a;
    bool b_internal = false;
  };
  std::vector<LoadedFlank> loaded_flanks;
  // A train of several stages: per gear pair the stage it meshes in, the mesh frequency its
  // harmonics are sought at and, in a planetary stage, the planet local-fault frequency (0: none).
  // Empty: every pair belongs to the one stage `frequencies` describes.
  struct PairStage {
    PairId pair;
    std::string stage;
    double mesh_hz = 0;
    double planet_fault_hz = 0;
  };
  std::vector<PairStage> pair_stages;
  // A train of several stages: per stage, θ_in − ratio·θ_out less its value at the start poses
  // (the assembly phase) is its transmission error, each absolute angle the sum of the logged
  // (parent-relative) angles of its chain's bodies.
  struct StageTe {
    std::string stage;
    std::vector<std::string> input_chain, output_chain;
    double ratio = 0;
    double assembly_phase_rad = 0;
  };
  std::vector<StageTe> stage_te;
};

}  // namespace gearsim
