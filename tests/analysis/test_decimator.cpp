// Decimation through an anti-aliasing filter: point-sampling folds the 24th mesh harmonic onto the
// mesh frequency and the filter removes it; mesh harmonics keep amplitude and phase; constants and
// straight lines pass exactly; streaming and whole records agree; bad input is refused by name.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "analysis/decimator.hpp"
#include "analysis/spectrum.hpp"
#include "core/errors.hpp"
#include "tests/analysis/synthetic_signals.hpp"

namespace gearsim {
namespace test_decimator {

using test::kTwoPi;

// The paper's run: 2e-5 s steps (50 kHz), contacts.csv at 2 kHz, mesh frequency 320 Hz.
constexpr double kStepRate = 50000.0, kOutputRate = 2000.0, kMesh = 320.0;

const DecimationFilter& paper_filter() {
  static const DecimationFilter f = design_decimation_filter(kStepRate, kOutputRate, {960.0, 100.0});
  return f;
}

// Outputs whose filter window lies wholly inside the n inputs (no edge-held value in it).
bool interior(const DecimationFilter& f, std::size_t j, std::size_t n) {
  const std::size_t centre = j * static_cast<std::size_t>(f.ratio);
  return centre >= f.group_delay_samples && centre + f.group_delay_samples < n;
}

void expect_input_error_naming(const std::function<void()>& call, const std::vector<std::string>& words) {
  try {
    call();
    ADD_FAILURE() << "expected InputError";
  } catch (const InputError& e) {
    for (const std::string& w : words) EXPECT_NE(std::string(e.what()).find(w), std::string::npos) << "'" << w << "' not in: " << e.what();
  }
}

TEST(DecimatorDesign, PaperCaseMeetsItsSpecification) {
  const DecimationFilter& f = paper_filter();
  EXPECT_EQ(f.ratio, 25);
  EXPECT_DOUBLE_EQ(f.stopband_edge_hz, 1040.0);  // f_out − f_pass
  ASSERT_EQ(f.length() % 2, 1u);
  EXPECT_EQ(f.group_delay_samples, (f.length() - 1) / 2);
  EXPECT_DOUBLE_EQ(f.group_delay_s, static_cast<double>(f.group_delay_samples) / kStepRate);
  // Linear phase: exactly symmetric taps. Unity DC gain: Σh = 1 to the rounding of L sums.
  double sum = 0.0;
  for (std::size_t n = 0; n < f.length(); ++n) {
    EXPECT_EQ(f.taps[n], f.taps[f.length() - 1 - n]);
    sum += f.taps[n];
  }
  EXPECT_NEAR(sum, 1.0, 1e-13);
  EXPECT_GE(f.stopband_attenuation_dB, 100.0);
  // A window design has the same ripple δ in both bands (the window's sidelobes set both);
  // ×2 leaves room for the normalisation and for the stopband being measured at its worst lobe.
  EXPECT_LE(f.passband_ripple, 2.0 * std::pow(10.0, -100.0 / 20.0));
  // Kaiser's length–bandwidth relation, L·Δf/f_in ≈ (A − 7.95)/(2.285·2π), within 5 %.
  const double time_bandwidth = static_cast<double>(f.length()) * (1040.0 - 960.0) / kStepRate;
  EXPECT_NEAR(time_bandwidth, (100.0 - 7.95) / (2.285 * kTwoPi), 0.05 * time_bandwidth);
}

TEST(DecimatorDesign, ReportedFiguresAgreeWithTheResponseEvaluatedDirectly) {
  // The design measures on a 16× grid by FFT; here H(f) summed directly on an independent 8× grid
  // cannot exceed those figures by more than a lobe's sampling error, 0.5 % (constants.hpp).
  const DecimationFilter& f = paper_filter();
  const double step = kStepRate / (8.0 * static_cast<double>(f.length()));
  double ripple = 0.0, stop = 0.0;
  for (double fr = 0.0; fr <= f.passband_edge_hz; fr += step) ripple = std::max(ripple, std::abs(frequency_response(f, fr) - 1.0));
  for (double fr = f.stopband_edge_hz; fr <= kStepRate / 2; fr += step) stop = std::max(stop, std::abs(frequency_response(f, fr)));
  EXPECT_LE(ripple, 1.005 * f.passband_ripple);
  EXPECT_LE(stop, 1.005 * std::pow(10.0, -f.stopband_attenuation_dB / 20.0));
  EXPECT_NEAR(frequency_response(f, 0.0), 1.0, 1e-13);  // DC gain 1
}

TEST(DecimatorAliasing, The24thMeshHarmonicFoldsOnto320HzUnlessFiltered) {
  // 7680 Hz = 24·320 Hz = 4·2 kHz − 320 Hz: sampled every 25th step it reads as 320 Hz.
  const double f_high = 24.0 * kMesh;
  const DecimationFilter& f = paper_filter();
  const std::size_t n = 60000;  // 1.2 s of steps
  const std::vector<double> x = test::tone(n, kStepRate, f_high, 1.0);
  const UniformSignal y = decimate(x, f);
  // 2000 outputs (1 s, 1 Hz bins: 320 Hz on a bin) clear of the edge-held ends.
  const std::size_t first = f.group_delay_samples / 25 + 1, count = 2000;
  ASSERT_TRUE(interior(f, first + count - 1, n));
  std::vector<double> point(count), filtered(count);
  for (std::size_t i = 0; i < count; ++i) {
    point[i] = x[(first + i) * 25];
    filtered[i] = y.values[first + i];
  }
  const Spectrum sp = amplitude_spectrum(point, kOutputRate);
  const Spectrum sf = amplitude_spectrum(filtered, kOutputRate);
  const std::size_t bin = nearest_bin(sp, kMesh);
  // Point samples are exactly cos(2π·320·t): a Hann window reads an on-bin tone exactly.
  EXPECT_NEAR(sp.amplitude[bin], 1.0, 1e-6);
  // Filtered, the folded line is the filter's gain at 7680 Hz: below −80 dB of the false line
  // (the design promises −100 dB over the whole stopband).
  EXPECT_LT(sf.amplitude[bin], 1e-4 * sp.amplitude[bin]);
  EXPECT_NEAR(sf.amplitude[bin], std::abs(frequency_response(f, f_high)), 1e-9);
}

TEST(DecimatorPassband, MeshHarmonicsKeepAmplitudeAndPhase) {
  // Zero phase: output j equals the input tone at t_j = t0 + j/f_out times H(f), with no delay;
  // so |y − x(t_j)| ≤ |H(f) − 1|·a, and within 0.1 % (1e-3 rad of phase) for the 3 harmonics.
  const DecimationFilter& f = paper_filter();
  const double t0 = 0.37, a = 2.5;
  const std::size_t n = 15000;  // 0.3 s
  for (const double fr : {kMesh, 2 * kMesh, 3 * kMesh}) {
    SCOPED_TRACE(fr);
    const double phase = 0.3 + fr / 1000.0;
    std::vector<double> x(n);
    for (std::size_t k = 0; k < n; ++k) x[k] = a * std::cos(kTwoPi * fr * (t0 + static_cast<double>(k) / kStepRate) + phase);
    const UniformSignal y = decimate(x, f, t0);
    double worst = 0.0;
    std::size_t checked = 0;
    for (std::size_t j = 0; j < y.values.size(); ++j) {
      if (!interior(f, j, n)) continue;
      const double t = y.start_time_s + static_cast<double>(j) / y.sample_rate_hz;
      worst = std::max(worst, std::abs(y.values[j] - a * std::cos(kTwoPi * fr * t + phase)));
      ++checked;
    }
    EXPECT_GT(checked, 400u);
    EXPECT_LE(worst, 1e-3 * a);
    EXPECT_LE(worst, std::abs(frequency_response(f, fr) - 1.0) * a + 1e-12 * a);
  }
}

TEST(DecimatorExactness, ConstantPassesEverywhereIncludingTheEnds) {
  // Σh = 1, and the held ends of a constant are the constant.
  const std::vector<double> x(10007, 3.25);
  const UniformSignal y = decimate(x, paper_filter());
  for (const double v : y.values) EXPECT_NEAR(v, 3.25, 1e-12 * 3.25);
}

TEST(DecimatorExactness, StraightLinePassesAwayFromTheEnds) {
  // Symmetric taps: the pairs of a line sum to twice its centre value, so y_j = x(t_j) exactly.
  const std::size_t n = 20000;
  std::vector<double> x(n);
  for (std::size_t k = 0; k < n; ++k) x[k] = 2.0 - 40.0 * static_cast<double>(k) / kStepRate;
  const double scale = 2.0 + 40.0 * static_cast<double>(n) / kStepRate;
  const UniformSignal y = decimate(x, paper_filter());
  std::size_t checked = 0;
  for (std::size_t j = 0; j < y.values.size(); ++j) {
    if (!interior(paper_filter(), j, n)) continue;
    EXPECT_NEAR(y.values[j], 2.0 - 40.0 * static_cast<double>(j) / kOutputRate, 1e-12 * scale);
    ++checked;
  }
  EXPECT_GT(checked, 600u);
}

TEST(DecimatorStream, MatchesTheWholeRecordForEveryChannel) {
  // One kernel, the same values in the same order: the same bits — for records shorter
  // than the filter (every output edge-held, all returned by finish()), one output long, and long;
  // at the paper's ratio and at 1e-5 s steps (R = 50, L = 8 017).
  const DecimationFilter fine = design_decimation_filter(2.0 * kStepRate, kOutputRate, {960.0, 100.0});
  for (const DecimationFilter* f : {&paper_filter(), &fine}) {
    const std::size_t ratio = static_cast<std::size_t>(f->ratio);
    for (const std::size_t n : {std::size_t{1}, ratio + 1, f->group_delay_samples, f->length() + 3,
                                std::size_t{12345}}) {  // 12345: not a multiple of R, the end falls between outputs
      SCOPED_TRACE(testing::Message() << "R " << ratio << ", n " << n);
      const double t0 = 1.5;
      const double rate = f->input_rate_hz;
      std::array<std::vector<double>, 3> columns = {test::tone(n, rate, 640.0, 1.0), test::white_noise(n, 0.5, 7), std::vector<double>(n)};
      test::add(columns[0], test::tone(n, rate, 7680.0, 0.3, 1.0));
      for (std::size_t k = 0; k < n; ++k) columns[2][k] = 100.0 + static_cast<double>(k);
      Decimator d(*f, 3, t0);
      std::vector<DecimatedRow> streamed;
      for (std::size_t k = 0; k < n; ++k) {
        const std::array<double, 3> row = {columns[0][k], columns[1][k], columns[2][k]};
        if (auto out = d.push(row)) streamed.push_back(std::move(*out));
      }
      for (DecimatedRow& out : d.finish()) streamed.push_back(std::move(out));
      for (std::size_t c = 0; c < 3; ++c) {
        SCOPED_TRACE(c);
        const UniformSignal whole = decimate(columns[c], *f, t0);
        ASSERT_EQ(streamed.size(), whole.values.size());
        for (std::size_t j = 0; j < whole.values.size(); ++j) {
          EXPECT_EQ(streamed[j].values[c], whole.values[j]);
          EXPECT_EQ(streamed[j].time_s, t0 + static_cast<double>(j) / kOutputRate);
        }
      }
    }
  }
}

TEST(DecimatorStream, ManyChannelsAreEachTheirOwnWholeRecord) {
  // The outputs are summed for up to 8 channels side by side: 11 channels (one block of 8, one of
  // 3), each a different signal, and each the whole-record answer bit for bit.
  const DecimationFilter& f = paper_filter();
  const std::size_t n = 6000, channels = 11;
  std::vector<std::vector<double>> columns;
  for (std::size_t c = 0; c < channels; ++c) {
    columns.push_back(test::white_noise(n, 1.0 + static_cast<double>(c), 100 + c));
    test::add(columns.back(), test::tone(n, kStepRate, 320.0 * static_cast<double>(c + 1), 2.0));
  }
  Decimator d(f, channels);
  std::vector<DecimatedRow> streamed;
  std::vector<double> row(channels);
  for (std::size_t k = 0; k < n; ++k) {
    for (std::size_t c = 0; c < channels; ++c) row[c] = columns[c][k];
    if (auto out = d.push(row)) streamed.push_back(std::move(*out));
  }
  for (DecimatedRow& out : d.finish()) streamed.push_back(std::move(out));
  for (std::size_t c = 0; c < channels; ++c) {
    SCOPED_TRACE(c);
    const UniformSignal whole = decimate(columns[c], f);
    ASSERT_EQ(streamed.size(), whole.values.size());
    for (std::size_t j = 0; j < whole.values.size(); ++j) EXPECT_EQ(streamed[j].values[c], whole.values[j]);
  }
}

TEST(DecimatorStream, EachOutputIsTheFilterCentredOnItsInput) {
  // Against the definition, summed apart in long double: y_j = Σ_n h_n·x(jR + n − M), x held at
  // its first value before the record and its last after (white noise, 3 000 samples at R = 25).
  const DecimationFilter& f = paper_filter();
  const std::size_t n = 3000;
  const auto m = static_cast<long long>(f.group_delay_samples), ratio = static_cast<long long>(f.ratio);
  const std::vector<double> x = test::white_noise(n, 1.0, 11);
  Decimator d(f, 1);
  std::vector<double> y;
  for (const double v : x)
    if (auto out = d.push(std::span<const double>(&v, 1))) y.push_back(out->values[0]);
  for (const DecimatedRow& out : d.finish()) y.push_back(out.values[0]);
  ASSERT_EQ(y.size(), (n - 1) / static_cast<std::size_t>(ratio) + 1);
  for (std::size_t j = 0; j < y.size(); ++j) {
    long double sum = 0;
    for (std::size_t t = 0; t < f.length(); ++t) {
      const long long at = static_cast<long long>(j) * ratio + static_cast<long long>(t) - m;
      const std::size_t k = static_cast<std::size_t>(std::clamp(at, 0LL, static_cast<long long>(n) - 1));
      sum += static_cast<long double>(f.taps[t]) * x[k];
    }
    EXPECT_NEAR(y[j], static_cast<double>(sum), 1e-13) << "output " << j;
  }
}

TEST(DecimatorStream, AnOutputIsReadyWhenTheFiltersRightHalfHasArrived) {
  const DecimationFilter& f = paper_filter();
  Decimator d(f, 1);
  std::size_t produced = 0;
  for (std::size_t k = 0; k < 10000; ++k) {
    const double v = std::sin(static_cast<double>(k));
    const auto out = d.push(std::span<const double>(&v, 1));
    const bool expected = k >= f.group_delay_samples && (k - f.group_delay_samples) % 25 == 0;
    ASSERT_EQ(out.has_value(), expected) << "input " << k;
    if (out) {
      EXPECT_EQ((k - f.group_delay_samples) / 25, produced++);
    }
  }
  EXPECT_EQ(d.outputs(), produced);
}

TEST(DecimatorStream, FinishEndsAtTheLastInputTime) {
  // Outputs j·R ≤ k_last: the last output time ≤ the last input time < the next output time.
  const DecimationFilter& f = paper_filter();
  const std::size_t m = f.group_delay_samples;
  const double t0 = 0.25;
  for (const std::size_t n : {std::size_t{1}, std::size_t{2}, std::size_t{24}, std::size_t{25}, std::size_t{26}, m, m + 1, f.length(),
                              f.length() + 24, std::size_t{9999}}) {
    SCOPED_TRACE(n);
    Decimator d(f, 2, t0);
    std::vector<double> times;
    for (std::size_t k = 0; k < n; ++k) {
      const std::array<double, 2> row = {1.0, static_cast<double>(k)};
      if (auto out = d.push(row)) times.push_back(out->time_s);
    }
    for (const DecimatedRow& out : d.finish()) times.push_back(out.time_s);
    EXPECT_EQ(times.size(), (n - 1) / 25 + 1);
    EXPECT_EQ(d.outputs(), times.size());
    const double last_input_s = t0 + static_cast<double>(n - 1) / kStepRate;
    EXPECT_LE(times.back(), last_input_s + 1e-12);
    EXPECT_GT(times.back() + 1.0 / kOutputRate, last_input_s + 1e-12);
  }
  Decimator empty(f, 1);
  EXPECT_TRUE(empty.finish().empty());
}

TEST(DecimatorInput, BadValuesAreRefusedByName) {
  expect_input_error_naming([] { design_decimation_filter(50000.0, 2100.0); }, {"2100", "23.8", "not an integer"});
  expect_input_error_naming([] { design_decimation_filter(50000.0, 50000.0); }, {"at least twice"});
  expect_input_error_naming([] { design_decimation_filter(50000.0, 2000.0, {1000.0}); }, {"passband edge 1000 Hz"});
  expect_input_error_naming([] { design_decimation_filter(50000.0, 2000.0, {1500.0}); }, {"passband edge 1500 Hz"});
  expect_input_error_naming([] { design_decimation_filter(NAN, 2000.0); }, {"input rate", "nan"});
  expect_input_error_naming([] { design_decimation_filter(50000.0, 2000.0, {std::nullopt, INFINITY}); }, {"attenuation", "inf"});
  expect_input_error_naming([] { decimate({1.0, 2.0, NAN, 4.0}, paper_filter()); }, {"sample 2", "nan"});
  Decimator d(paper_filter(), 2);
  for (int k = 0; k < 3; ++k) d.push(std::array<double, 2>{1.0, 2.0});
  expect_input_error_naming([&] { d.push(std::array<double, 2>{1.0, INFINITY}); }, {"row 3", "column 1", "inf"});
  expect_input_error_naming([&] { d.push(std::array<double, 1>{1.0}); }, {"holds 1 values, expected 2"});
  EXPECT_EQ(d.inputs(), 3u);  // a refused row is not taken
}

}  // namespace test_decimator
}  // namespace gearsim
