// Decimation: a signal sampled at f_in (one row per simulation step) kept at f_out = f_in/R through
// the anti-aliasing filter of decimation_filter.hpp, instead of point-sampling every R-th step
// (which folds everything above f_out/2 onto the kept band). Streaming (Decimator, several
// channels per row, as a CSV row) or on a whole record (decimate); both give the same numbers.
//  - Zero phase: output j is the filter centred on input j·R, at time t0 + j/f_out, so the time
//    column needs no delay correction. It is therefore ready only once the filter's right half,
//    group_delay_samples more inputs, has arrived.
//  - Cost: only output instants are computed, (L + 1)/2 multiplies per channel per output; memory
//    is a ring buffer of 2·L values per channel, whatever the length of the run.
//  - Ends: before the first input the signal is taken to hold its first value and, at finish(),
//    after the last input its last value. The first and last group_delay_s of output are thus
//    edge-held: a constant passes exactly there, anything else is pulled towards the held value.
//    Outputs run up to the last input time, so the output ends when the per-step log ends.
// Not a resampler for non-integer ratios or non-uniform samples (resample.hpp).
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "analysis/decimation_filter.hpp"
#include "analysis/resample.hpp"

namespace gearsim {

struct DecimatedRow {
  double time_s = 0;  // t0 + j/f_out, s
  std::vector<double> values;  // one per channel, in the input's units
};

class Decimator {
 public:
  // `channels` values per row (≥ 1; InputError otherwise); the first row is at start_time_s, s.
  Decimator(DecimationFilter filter, std::size_t channels, double start_time_s = 0);

  // Feeds input row k (at t0 + k/f_in) and returns the output that became ready with it: output
  // j once row j·R + group_delay_samples has arrived, so at most one per row. Throws InputError
  // when the row does not hold `channels` values or a value is not finite (naming row, column
  // and value); the decimator is unchanged then.
  std::optional<DecimatedRow> push(std::span<const double> row);

  // Ends the input and returns the outputs still pending: every j with j·R ≤ the last row's k
  // (time ≤ the last input time; the next would be later), the last row held beyond the end.
  // None without input. Pushing or finishing after finish() is a bug (InternalError).
  std::vector<DecimatedRow> finish();

  const DecimationFilter& filter() const { return filter_; }
  std::size_t channels() const { return channels_; }
  std::size_t inputs() const { return inputs_; }  // rows pushed
  std::size_t outputs() const { return next_output_; }  // rows returned (push and finish)

 private:
  void append(std::span<const double> row);  // one row into the ring (real or held)
  std::optional<DecimatedRow> ready_output();  // output next_output_, if its window is complete

  DecimationFilter filter_;
  std::size_t channels_;
  double start_time_s_;
  std::size_t length_;  // L
  // 2·L rows of `channels` values (a row's channels side by side), each row written at rows p
  // and p + L: the last L rows are always contiguous, starting at row (appended_ mod L).
  std::vector<double> ring_;
  // Rows in the ring's stream: group_delay_samples copies of the first row, the inputs, then (at
  // finish) copies of the last row. Output j is centred on stream row j·R + group_delay_samples.
  std::size_t appended_ = 0;
  std::size_t inputs_ = 0;
  std::size_t next_output_ = 0;
  std::vector<double> last_row_;
  bool finished_ = false;
};

// x (uniform samples at f_in, the first at start_time_s) decimated to f_out: the numbers pushing
// x one sample at a time and finishing would give. Throws InputError as design_decimation_filter,
// on an empty record or on a non-finite sample (naming it).
UniformSignal decimate(const std::vector<double>& x, double input_rate_hz, double output_rate_hz,
                       const DecimationFilterOptions& options = {}, double start_time_s = 0);

// The same with a filter designed once (design_decimation_filter), for many records.
UniformSignal decimate(const std::vector<double>& x, const DecimationFilter& filter, double start_time_s = 0);

}  // namespace gearsim
