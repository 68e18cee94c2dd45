// Where mesh harmonics meet natural frequencies. The train's rigid kinematics per unit speed of
// the drive (each mesh rolls without slip: z_a (ω_a − ω_c) = ∓ z_b (ω_b − ω_c) about the body c
// that carries it; welded bodies, torsional supports and motor-held joints do not turn relative
// to their parent), hence each mesh's frequency per rad/s of the drive, and the drive speeds at
// which its k-th harmonic equals each natural frequency (a Campbell table).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "linear/lumped_model.hpp"
#include "linear/modes.hpp"

namespace gearsim::linear {

struct MeshRate {
  int mesh = -1;  // index into LumpedModel::meshes
  double hz_per_rad_s = 0;  // mesh frequency per rad/s of the drive's speed
};

struct Crossing {
  int group = -1;  // ModalAnalysis::groups
  int mesh = -1;  // the first mesh of that mesh frequency
  int harmonic = 0;  // k
  double natural_frequency_hz = 0;
  double drive_speed_rad_s = 0;  // where k·f_mesh = f_n
};

struct Campbell {
  std::string drive;  // the body whose speed is the axis
  std::vector<MeshRate> rates;  // one per mesh
  std::optional<double> operating_speed_rad_s;  // the drive's motor target, when it has one
  std::vector<Crossing> crossings;  // by natural frequency, then harmonic
  std::string why_not;  // why there is no table (kinematics not determined), else ""
};

// `harmonics`: k = 1 … harmonics; crossings above `max_speed_rad_s` are left out.
Campbell campbell(const LumpedModel& model, const physics::WorldStructure& structure, const ModalAnalysis& modes, int harmonics,
                  double max_speed_rad_s);

}  // namespace gearsim::linear
