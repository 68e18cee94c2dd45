#include "analysis/decimator.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <string>
#include <utility>

#include "core/errors.hpp"

namespace gearsim {
namespace {

// The filter centred on the middle of a window of 2·m_half + 1 consecutive samples, for `count`
// (≤ kChannelBlock) channels whose samples lie interleaved (sample i of channel c at
// window[i·stride + c]), into y[c]. Summed in mirrored pairs (half the multiplies; a straight line
// passes exactly, its pairs sum to twice the centre), each channel in the same order, the
// channels side by side: independent chains of additions instead of one chain m_half long whose
// latency set the time. The one kernel for streaming (a ring of rows) and whole records (one
// channel, stride 1), so both give the same bits.
constexpr std::size_t kChannelBlock = 8;
void decimation_centred_outputs(const std::vector<double>& taps, const double* window, std::size_t stride, std::size_t count,
                                std::size_t m_half, double* y) {
  double acc[kChannelBlock];
  const double* centre = window + m_half * stride;
  for (std::size_t c = 0; c < count; ++c) acc[c] = taps[m_half] * centre[c];
  for (std::size_t m = 0; m < m_half; ++m) {
    const double h = taps[m];
    const double *lo = window + m * stride, *hi = window + (2 * m_half - m) * stride;
    for (std::size_t c = 0; c < count; ++c) acc[c] += h * (lo[c] + hi[c]);
  }
  for (std::size_t c = 0; c < count; ++c) y[c] = acc[c];
}

std::string decimator_number(double v) {
  std::ostringstream out;
  out.precision(10);
  out << v;
  return out.str();
}

}  // namespace

Decimator::Decimator(DecimationFilter filter, std::size_t channels, double start_time_s)
    : filter_(std::move(filter)), channels_(channels), start_time_s_(start_time_s), length_(filter_.length()) {
  if (channels_ == 0) throw InputError("decimator: expected at least 1 channel, got 0");
  if (!std::isfinite(start_time_s_))
    throw InputError("decimator: start time must be a finite number of s, got " + decimator_number(start_time_s_));
  GEARSIM_CHECK(length_ % 2 == 1 && filter_.group_delay_samples == (length_ - 1) / 2 && filter_.ratio >= 1,
                "the decimator needs a filter from design_decimation_filter");
  ring_.assign(channels_ * 2 * length_, 0.0);
}

void Decimator::append(std::span<const double> row) {
  const std::size_t p = appended_ % length_;
  std::copy(row.begin(), row.end(), ring_.begin() + static_cast<std::ptrdiff_t>(p * channels_));
  std::copy(row.begin(), row.end(), ring_.begin() + static_cast<std::ptrdiff_t>((p + length_) * channels_));
  ++appended_;
}

std::optional<DecimatedRow> Decimator::ready_output() {
  // Output j needs stream rows j·R … j·R + L − 1: ready when exactly those are the last L.
  const std::size_t first = next_output_ * static_cast<std::size_t>(filter_.ratio);
  if (appended_ < first + length_) return std::nullopt;
  GEARSIM_CHECK(appended_ == first + length_, "the decimator computes every output as soon as it is ready");
  const std::size_t start = appended_ % length_;
  DecimatedRow out;
  out.time_s = start_time_s_ + static_cast<double>(next_output_) / filter_.output_rate_hz;
  out.values.resize(channels_);
  for (std::size_t c = 0; c < channels_; c += kChannelBlock)
    decimation_centred_outputs(filter_.taps, ring_.data() + start * channels_ + c, channels_, std::min(kChannelBlock, channels_ - c),
                               filter_.group_delay_samples, out.values.data() + c);
  ++next_output_;
  return out;
}

std::optional<DecimatedRow> Decimator::push(std::span<const double> row) {
  GEARSIM_CHECK(!finished_, "no input after Decimator::finish()");
  if (row.size() != channels_)
    throw InputError("decimator: input row " + std::to_string(inputs_) + " holds " + std::to_string(row.size()) + " values, expected " +
                     std::to_string(channels_));
  for (std::size_t c = 0; c < channels_; ++c)
    if (!std::isfinite(row[c]))
      throw InputError("decimator: input row " + std::to_string(inputs_) +
                       " (t = " + decimator_number(start_time_s_ + static_cast<double>(inputs_) / filter_.input_rate_hz) + " s), column " +
                       std::to_string(c) + " is not finite (" + decimator_number(row[c]) + ")");
  // Before the first row the signal holds its value: the left half of output 0's window.
  if (inputs_ == 0)
    for (std::size_t k = 0; k < filter_.group_delay_samples; ++k) append(row);
  append(row);
  ++inputs_;
  last_row_.assign(row.begin(), row.end());
  return ready_output();
}

std::vector<DecimatedRow> Decimator::finish() {
  GEARSIM_CHECK(!finished_, "Decimator::finish() once");
  finished_ = true;
  std::vector<DecimatedRow> out;
  if (inputs_ == 0) return out;
  // Outputs centred on inputs up to the last one, the last row held for their right halves.
  const std::size_t last_input = inputs_ - 1;
  const auto ratio = static_cast<std::size_t>(filter_.ratio);
  while (next_output_ * ratio <= last_input) {
    append(last_row_);
    if (auto row = ready_output()) out.push_back(std::move(*row));
  }
  return out;
}

UniformSignal decimate(const std::vector<double>& x, const DecimationFilter& filter, double start_time_s) {
  if (x.empty()) throw InputError("decimate: expected at least 1 sample, got 0");
  if (!std::isfinite(start_time_s))
    throw InputError("decimate: start time must be a finite number of s, got " + decimator_number(start_time_s));
  for (std::size_t k = 0; k < x.size(); ++k)
    if (!std::isfinite(x[k])) throw InputError("decimate: sample " + std::to_string(k) + " is not finite (" + decimator_number(x[k]) + ")");
  GEARSIM_CHECK(filter.length() % 2 == 1 && filter.group_delay_samples == (filter.length() - 1) / 2 && filter.ratio >= 1,
                "decimate needs a filter from design_decimation_filter");
  const std::size_t m_half = filter.group_delay_samples;
  const auto ratio = static_cast<std::size_t>(filter.ratio);
  // x with its first value held m_half samples before and its last m_half samples after.
  std::vector<double> held(x.size() + 2 * m_half, x.back());
  std::fill(held.begin(), held.begin() + static_cast<std::ptrdiff_t>(m_half), x.front());
  std::copy(x.begin(), x.end(), held.begin() + static_cast<std::ptrdiff_t>(m_half));
  UniformSignal y;
  y.start_time_s = start_time_s;
  y.sample_rate_hz = filter.output_rate_hz;
  y.values.resize((x.size() - 1) / ratio + 1);  // every j with j·R ≤ the last sample
  for (std::size_t j = 0; j < y.values.size(); ++j)
    decimation_centred_outputs(filter.taps, held.data() + j * ratio, 1, 1, m_half, &y.values[j]);
  return y;
}

UniformSignal decimate(const std::vector<double>& x, double input_rate_hz, double output_rate_hz, const DecimationFilterOptions& options,
                       double start_time_s) {
  return decimate(x, design_decimation_filter(input_rate_hz, output_rate_hz, options), start_time_s);
}

}  // namespace gearsim
