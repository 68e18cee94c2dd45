// The analysis of a finished run, as a library call: typed signals in (run_signals.hpp), a typed
// result out — per gear pair its force spectrum, mesh harmonics, sidebands and fault-family lines
// (pair_force_analysis.hpp); the transmission error's statistics (transmission_error.hpp); per
// planet the angle-synchronous average of its sun mesh (synchronous_teeth.hpp); per counted gear
// its per-tooth loads from the tooth-contact log (tooth_loads.hpp). Everything over one window,
// from RunSignals::from_s to the end of the record. Knows no file, no JSON and no scenario:
// app/run_analysis reads the run folder and writes the result out.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "analysis/pair_force_analysis.hpp"
#include "analysis/run_signals.hpp"
#include "analysis/diagnosis.hpp"
#include "analysis/sensor_analysis.hpp"
#include "analysis/synchronous_teeth.hpp"
#include "analysis/tooth_loads.hpp"
#include "analysis/transmission_error.hpp"

namespace gearsim {

struct RunAnalysis {
  double from_s = 0, to_s = 0;  // the first and last analysed sample instants, s
  double sample_rate_hz = 0;  // of the output-rate samples in the window, Hz
  std::vector<PairForceAnalysis> pairs;  // every gear pair, in the order of RunSignals::pair_forces
  // Over the window; nothing without a TE series. min, max and peak_to_peak are those of the
  // band-limited signal the samples hold (band_limited.hpp), mean and rms the samples'.
  std::optional<TransmissionErrorStats> te;
  std::optional<double> te_samples_peak_to_peak_rad;  // the samples' own max − min
  // A train of several stages: each stage's transmission error (TrainDescription::stage_te), as te.
  struct StageTe {
    std::string stage;
    double ratio = 0;
    TransmissionErrorStats te;
    double samples_peak_to_peak_rad = 0;
  };
  std::vector<StageTe> stage_te;
  // Planetary: one per planet whose sun–planet pair is logged; nothing for a gear pair.
  std::optional<std::vector<SynchronousTeeth>> synchronous;
  std::string synchronous_note;  // why a planet has no synchronous average (a window under one turn), else ""

  // Per logged pair and side whose gear is counted and turns at least once in the window, in
  // log order (side a before b); nothing without a tooth-contact log.
  std::optional<std::vector<ToothLoads>> tooth_loads;
  // From the tooth loads: the faults and the teeth that only respond to them.
  std::optional<Diagnosis> diagnosis;
  // Per housing sensor (a planetary set's run with sensors.csv): planet-separated averages,
  // indicators, and the fault the sensor alone points to.
  std::vector<SensorAnalysis> sensors;
};

// Samples with time_s ≥ from_s.
std::size_t samples_from(const std::vector<double>& time_s, double from_s);

// InputError naming what is missing or inconsistent: fewer than kMinRunSamples samples from
// from_s on, a non-uniform time base, no gear pair, a series whose length differs from time_s,
// the angle of a planet or counted gear not among the signals; and as analyse_pair_force,
// synchronous_teeth and tooth_loads.
RunAnalysis analyze_signals(const RunSignals& signals, const TrainDescription& train);

}  // namespace gearsim
