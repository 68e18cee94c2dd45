// Per-tooth statistics of an angle-synchronous average: the mean of the averaged signal within
// each tooth's angular window, how far each tooth's mean stands from the other teeth's (a
// leave-one-out z-score), and the teeth whose |z| passes a threshold. Finds the odd tooth out;
// it does not say what is wrong with it, and a gear whose teeth are all equally worn looks healthy.
#pragma once

#include <optional>
#include <vector>

#include "analysis/angle_average.hpp"
#include "analysis/constants.hpp"

namespace gearsim {

struct ToothStatisticsOptions {
  int teeth = 0;  // z (≥ 2)
  // Body angle at which tooth 0's window begins, rad. Tooth k's window is
  // [tooth0_start_rad + k·2π/z, tooth0_start_rad + (k+1)·2π/z), in the angle's own direction of
  // increase, reduced modulo 2π.
  double tooth0_start_rad = 0;
  // When set, only samples with a value > this count ("in mesh", e.g. a contact force above a
  // few N); otherwise every sample in the window counts. Signal unit.
  std::optional<double> in_mesh_threshold;
  double z_threshold = analysis_constants::kDefaultToothZThreshold;  // |z| above this: faulty
};

struct ToothStatistic {
  int tooth = 0;
  int samples = 0;  // averaged samples that counted in the window
  double mean = 0;  // their mean, signal unit
  // (mean − mean of the other teeth)/(sample standard deviation of the other teeth's means).
  // ±infinity when the others agree exactly and this tooth differs; 0 when all agree.
  double z_score = 0;
  bool faulty = false;  // |z_score| > z_threshold
};

struct ToothStatistics {
  std::vector<ToothStatistic> teeth;  // tooth 0 … z−1
  std::vector<int> faulty_teeth;  // indices with |z| > z_threshold, increasing
  double z_threshold = 0;
};

// (value − mean of the others)/(sample standard deviation of the others) for each value: how far
// one tooth's figure stands from the rest. ±infinity when the others agree exactly and this one
// differs; 0 when all agree. Throws InputError on fewer than 3 values.
std::vector<double> leave_one_out_z_scores(const std::vector<double>& values);

// The teeth whose |z| passes z_threshold AND whose value differs from the mean of the others by
// more than min_relative_deviation of it (kDefaultToothMinRelativeDeviation: the z alone flags
// tiny scatter when healthy teeth agree very closely). Increasing order.
std::vector<int> teeth_standing_apart(const std::vector<double>& values, const std::vector<double>& z_scores, double z_threshold,
                                      double min_relative_deviation);

// Throws InputError on fewer than 3 teeth (a leave-one-out spread needs two others), fewer
// average samples than teeth, a non-positive z threshold, or a tooth window with no counting
// sample (the message names the tooth: lower the in-mesh threshold or raise the sampling).
ToothStatistics tooth_statistics(const AngleAverage& average, const ToothStatisticsOptions& options);

}  // namespace gearsim
