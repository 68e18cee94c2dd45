// Inside gear recognition (gear_recognition.hpp), shared by its sources: the toothed loop's
// envelope and teeth (gear_recognition_loop.cpp), the involute fits of the flanks
// (gear_recognition_flanks.cpp) and the choice of a standard module and pressure angle
// (gear_recognition_standard.cpp); recognise_gear (gear_recognition.cpp) runs them in turn.
// Not for use outside geometry/.
#pragma once

#include <Eigen/Core>
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "geometry/constants.hpp"
#include "geometry/gear_recognition.hpp"
#include "geometry/outline.hpp"

namespace gearsim::recognition_detail {

using gearsim::constants::kPi;

// Tooth depth of the ISO 53 basic rack (addendum 1 + dedendum 1.25), in modules.
constexpr double kRackDepth = 2.25;

// A loop's teeth, if it has any: count, wave amplitude, symmetry and the envelope about its centroid.
struct LoopTeeth {
  int teeth = 0;
  double amplitude_m = 0, residual_m = 0, r_min = 0, r_max = 0;
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  std::vector<double> env;
  std::string why;  // why not, when teeth == 0
};

// r(θ_i), θ_i = 2πi/N, about c: the farthest crossing of each ray for the outer loop, the nearest
// for a hole. Empty when some ray misses the loop (c outside it).
std::vector<double> radial_envelope(const Polygon2& p, const Eigen::Vector2d& c, bool outer);

// rms of r(θ) − r(θ + 2π/k), m.
double symmetry_residual(const std::vector<double>& env, int k);

// The loop's teeth about its centroid, or why it has none.
LoopTeeth loop_teeth(const Polygon2& p, bool outer);

// Each tooth's crossings of the mid-depth circle (see gear_recognition_loop.cpp); empty when the
// crossings do not pair up into z teeth.
std::vector<std::pair<double, double>> tooth_crossings(const LoopTeeth& lt, bool internal);

// Tooth 0's centre line: the mean of the teeth's mid-crossing angles, modulo the pitch.
double tooth0_angle(const std::vector<std::pair<double, double>>& teeth);

// The axis: the common centre of the tip and root circles (see gear_recognition_loop.cpp).
Eigen::Vector2d refined_axis(const Polygon2& loop, const LoopTeeth& lt);

// Points of one side of the teeth in tooth frames: radius and half-angle from the centre line.
struct FlankPoints {
  std::vector<double> r, y;
  std::vector<int> tooth;
};

// The loop's points split by side of their tooth's centre line: [0] Ccw, [1] Cw.
std::array<FlankPoints, 2> flank_points(const Polygon2& loop, const RecognisedGear& g);

// inv(acos(r_b / r)), the involute function at radius r of base radius r_b (0 inside the base circle).
double inv_at(double rb, double r);

// One side of the teeth fitted with one involute, outliers dropped (see InvoluteFit).
InvoluteFit fit_flank(const FlankPoints& f, const RecognisedGear& g);

// Module and pressure angle from the base pitch, the depth and the tooth thickness (see
// RecognisedGear::standard); sets module_m, pressure_angle_rad, standard, reference_radius_m,
// reference_thickness_m and profile_shift.
void module_and_pressure_angle(RecognisedGear& g);

}  // namespace gearsim::recognition_detail
