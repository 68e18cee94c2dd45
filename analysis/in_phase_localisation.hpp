// Which planet of an in-phase set (z_s/N whole: every planet's tooth k meets the sun at the same
// instant) a sensor event belongs to, from the planets' separated averages alone. What it rests
// on: the planets share one load, so when planet j's flawed tooth sheds (or takes) load ΔF, the
// others take (or shed) it between them at the same instant — Σ_k ΔF_k = 0. Each planet's
// separated average hears its own mesh through the same path (same sensor, same window position),
// so at the common tooth the event waveforms are u·ΔF_k: planet j's is the largest
// (|ΔF_j| = Σ_{k≠j}|ΔF_k| ≥ each responder's) and of opposite sign to every responder's, while the
// responders agree with each other. A planet is named only when the waveforms show exactly that
// pattern, significantly; events of one sign on every planet (a sun tooth, a torque step) name
// none. Not a detector of a fault's size, and not for sequentially phased sets (sensor_analysis).
#pragma once

#include <string>
#include <vector>

namespace gearsim {

struct InPhaseEvent {
  double event_rms_m_s2 = 0;  // RMS of the difference signal over the event window
  double background_rms_m_s2 = 0;  // RMS of the difference signal more than one pitch from it
};

struct InPhaseLocalisation {
  int samples_per_revolution = 0;
  int event_tooth = -1;  // the tooth facing the sun at the event's largest excursion (every planet's)
  std::vector<InPhaseEvent> planets;
  // Normalised correlation ⟨v_j, v_k⟩/(|v_j||v_k|) of the planets' event waveforms.
  std::vector<std::vector<double>> correlation;
  double min_correlation = 0;  // |ρ| a pattern's correlation must reach (2/√M, M samples in the window)
  bool event = false;  // some planet's event stands kInPhaseEventOverBackground over its background
  int named = -1;  // the planet whose event opposes all the others', -1: none
  double confidence = 0;  // named: the weakest |ρ| of its pattern (1: exact ± copies)
  std::string reason;  // why this planet, or why none
};

// means[k]: planet k's separated average over one turn relative to the carrier (all on one grid of
// samples_per_revolution), sun_direction_rad[k]: its turn at which its tooth 0 faces the sun
// (tooth t at sun_direction − t·2π/teeth); sensor_samples_per_revolution: sensor samples per such
// turn (sets M). InputError on fewer than two planets, unequal grids or a grid under 4·teeth.
InPhaseLocalisation localise_in_phase(const std::vector<std::vector<double>>& means, const std::vector<double>& sun_direction_rad,
                                      int teeth, double sensor_samples_per_revolution);

}  // namespace gearsim
