// The output-rate logs of a run as an observer, one row per output sample, 17 significant digits,
// SI units in every column name:
//  - state.csv: every body's angle and speed — POINT SAMPLES of the step at the sample time (slow
//    states; their spectra are not reported from this file) — and, when the scenario names a
//    transmission, its error `te_rad` (θ_in − ratio·θ_out less its value at the start poses, the
//    assembly phase: 0 for gears that start in mesh unloaded) ANTI-ALIASED like the forces below (the peak-to-peak and
//    spectra `analyze` reports; the per-step TE carries the contact modes' ringing, which a point
//    sample folds in and which is not converged at the usual steps) and `te_point_rad`, the point
//    sample; bearing displacements, point samples.
//  - contacts.csv: per gear pair `<a>__<b>_force_N`, the summed normal force ANTI-ALIASED: every
//    step's force through the decimation filter of analysis/decimation_filter.hpp (passband to
//    0.48·f_out, 100 dB above f_out − f_pass), so that its spectrum holds no folded mesh
//    harmonics or contact ringing; `_force_point_N`, the same force point-sampled (what the paper
//    logged; aliased); `_tooth_pairs` and `_max_depth_um`, point samples (counts and maxima are
//    not band-limited signals).
// The filter is zero-phase (no delay in the time column); its first and last half-length
// (filter().group_delay_s, 40 ms at 50 kHz → 2 kHz) hold the end values (decimator.hpp): the
// analysis leaves them out. Rows of both files are written once their filtered values are ready.
// A run that stops between samples ends both files with a row at the step it stopped on; that row
// carries point samples in every column.
#pragma once

#include <deque>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "analysis/decimator.hpp"
#include "core/output_file.hpp"
#include "physics/scenario.hpp"
#include "sim/observer.hpp"

namespace gearsim::sim {

class CsvLogs : public Observer {
 public:
  // DIR/state.csv and DIR/contacts.csv, created when the run starts (a scenario the world refuses
  // leaves no empty logs) under temporary names; OutputError naming the file when one cannot be. The scenario
  // must outlive the observer.
  CsvLogs(const std::filesystem::path& dir, const physics::Scenario& scenario);
  void on_start(const physics::World& world) override;
  void on_step(const physics::World& world) override;
  void on_sample(const physics::World& world) override;
  // Writes the last rows and puts both files in place (core/output_file.hpp); OutputError naming
  // each that could not be written (that one is not put in place).
  void on_stop(const physics::World& world) override;
  bool write_failed() const override;
  // The anti-aliasing filter of the force and TE columns; none when every step is a sample.
  const std::optional<DecimationFilter>& force_filter() const { return filter_; }

 private:
  // The point-sampled part of a sample's rows, kept until its filtered values are ready.
  struct PointRow {
    long sample = 0;  // j: the row's time is j/f_out (−1: a stop between samples)
    double time_s = 0;
    std::vector<double> force_N, depth_um;
    std::vector<int> tooth_pairs;
    double te_rad = 0;  // point sample of the transmission error
    std::string state_head, state_tail;  // state.csv's text before and after the TE columns
  };
  PointRow point_row(const physics::World& world, long sample) const;
  void write_row(const PointRow& row, const std::vector<double>& filtered);
  void write_ready(const DecimatedRow& out);
  std::vector<double> filtered_channels(const physics::World& world) const;
  std::vector<double> filtered_point(const PointRow& row) const;
  double transmission_error_rad(const physics::World& world) const;

  std::filesystem::path dir_;
  const physics::Scenario& scenario_;
  std::unique_ptr<OutputFile> state_, contacts_;
  std::vector<std::pair<std::size_t, Eigen::Vector3d>> moving_;  // bodies on a ground bearing, start position
  struct Carried {  // a body on a bearing on a body that turns about the ground (a planet on its carrier)
    std::size_t body = 0, parent = 0;
    double parent_angle0 = 0;
    Eigen::Vector3d offset0 = Eigen::Vector3d::Zero(), parent0 = Eigen::Vector3d::Zero();
  };
  std::vector<Carried> carried_;
  int te_in_ = -1, te_out_ = -1;  // bodies of the transmission's input and output joints
  double assembly_phase_rad_ = 0;  // θ_in − ratio·θ_out of the start poses (before the first step)
  long every_ = 1;  // steps per output sample
  std::optional<DecimationFilter> filter_;
  std::optional<Decimator> decimator_;
  std::deque<PointRow> pending_;  // point rows whose filtered values are not ready yet
  std::size_t pairs_ = 0;
  std::string row_text_;  // write_row(): a row's text before it is written
};

}  // namespace gearsim::sim
