// Natural frequencies and mode shapes of a lumped model (lumped_model.hpp): the generalised
// eigenproblem K φ = ω² M φ on the coordinates the constraints leave free; frequencies that
// agree to 1e-7 are one natural frequency of that multiplicity; each mode's type from the
// structure of its shape; the share of its strain energy in each spring.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "linear/lumped_model.hpp"

namespace gearsim::linear {

// What moves in a mode. For a planetary set (bodies carried by another body: the planets; the
// rest: central members): rotational — the central members only turn; translational — they only
// translate; planet — they stay still and only the planets move; mixed — anything else (and
// every mode of a train without planets that both turns and translates).
enum class ModeType { Rigid, Rotational, Translational, Planet, Mixed };
const char* to_string(ModeType t);

struct Mode {
  double frequency_hz = 0;  // 0 for a rigid-body mode
  int group = -1;  // index into ModalAnalysis::groups
  ModeType type = ModeType::Mixed;
  Eigen::VectorXd shape;  // over all coordinates, mass-normalised (φᵀ M φ = 1)
  std::vector<double> energy_share;  // per model element, Σ = 1 (empty for rigid-body modes)
  // Rotational modes of a planetary set: every planet moves alike in its own radial/tangential
  // frame (Lin & Parker's property). False when there are no planets.
  bool planets_alike = false;
};

struct ModeGroup {
  double frequency_hz = 0;  // mean of its members
  int multiplicity = 0;
  ModeType type = ModeType::Mixed;  // Mixed when its members differ
  std::vector<int> modes;
};

struct ModalAnalysis {
  std::vector<Mode> modes;  // ascending frequency
  std::vector<ModeGroup> groups;  // ascending frequency
  int free_coordinates = 0;  // coordinates left by the constraints
};

ModalAnalysis solve_modes(const LumpedModel& model);

}  // namespace gearsim::linear
