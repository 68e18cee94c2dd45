// Angle-synchronous (time-synchronous) averaging: a signal sampled in time is resampled, by LINEAR
// INTERPOLATION in angle, onto a uniform grid of a reference body's rotation angle (e.g. a planet's
// rotation relative to the carrier), and the whole revolutions are averaged sample by sample.
// What is locked to that body's rotation stays; what is not (other bodies' meshes, noise) averages
// out. No anti-alias filter: the signal must hold no content above samples_per_revolution/2
// orders of the body, or that content folds down. Not an order-tracking spectrum.
#pragma once

#include <vector>

#include "analysis/constants.hpp"

namespace gearsim {

struct AngleAverage {
  // Body angles of the averaged samples, rad: angle_rad[j] = j·2π/samples_per_revolution, the
  // angle of the reference body reduced to [0, 2π) in its own angle signal's convention.
  std::vector<double> angle_rad;
  std::vector<double> mean;  // the average at angle_rad[j], signal unit
  int samples_per_revolution = 0;
  int revolutions = 0;  // whole revolutions averaged: each mean[j] is the mean of this many samples
};

// signal[i] and angle_rad[i] are sampled at the same instants; angle_rad is the reference body's
// rotation, strictly monotone (increasing, or decreasing for a body turning the negative way),
// unwrapped (not reduced to 2π). The average starts at the first grid angle (a multiple of
// 2π/samples_per_revolution) inside the record and uses every whole revolution after it.
// Throws InputError on different lengths, fewer than 2 samples, a non-monotone or non-finite
// angle, samples_per_revolution < 4, or a record shorter than one revolution.
AngleAverage angle_synchronous_average(const std::vector<double>& signal, const std::vector<double>& angle_rad,
                                       int samples_per_revolution = analysis_constants::kDefaultSamplesPerRevolution);

// How many whole revolutions of the grid angle_synchronous_average would average (0: the record
// is too short for it), from the angle's first and last samples.
long long synchronous_revolutions(const std::vector<double>& angle_rad,
                                  int samples_per_revolution = analysis_constants::kDefaultSamplesPerRevolution);

}  // namespace gearsim
