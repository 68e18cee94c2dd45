// The standard condition indicators of gear diagnostics, on a time-synchronous average (TSA: one
// revolution of the gear, samples_per_revolution points, angle_average.hpp) — the definitions of
// Lebold, McClintic, Campbell, Byington & Maynard, "Review of vibration analysis methods for
// gearbox diagnostics and prognostics", Proc. 54th MFPT, 2000 (docs/condition-monitoring.md):
//
//   regular signal  r_reg: the TSA's mesh orders k·z (k ≥ 1), their first sidebands k·z ± 1,
//                   and the shaft orders 1 and 2
//   difference d  = TSA − mean − r_reg
//   residual  res = TSA − mean − (mesh orders k·z, shaft orders 1 and 2): d plus the sidebands
//   RMS           = √(Σ x²/N)                                        (of the TSA about its mean)
//   crest factor  = max|x − x̄| / RMS
//   kurtosis      = N Σ(x − x̄)⁴ / (Σ(x − x̄)²)²                     (3 for Gaussian samples)
//   FM0           = (max x − min x) / Σ_k A(k·z)                     A: order amplitude
//   FM4           = kurtosis of d                                    (3 for a healthy gear)
//   M6A           = N² Σ(d − d̄)⁶ / (Σ(d − d̄)²)³                     (15 for Gaussian d)
//   NA4           = N Σ(res_M − r̄es_M)⁴ / ((1/M) Σ_j Σ_i (res_ij − r̄es_j)²)²
//                   the current residual's fourth moment over the mean variance of the M records
//                   so far (a trend indicator; one record: FM4 of the residual)
//   ER            = RMS(d) / RMS(mesh orders k·z)                    energy ratio
// Orders are integer multiples of the revolution; a component's amplitude is read from the DFT
// of the whole revolution (no window: a TSA is exactly periodic). No files.
#pragma once

#include <vector>

namespace gearsim {

// The amplitude of order k (k cycles per revolution) of one revolution x: 2|X_k|/N (|X_0|/N for k = 0).
double order_amplitude(const std::vector<double>& x, int order);

struct TsaSignals {
  std::vector<double> regular;  // mean removed
  std::vector<double> residual;
  std::vector<double> difference;
  std::vector<double> mesh;  // the mesh orders k·z alone
};

// The regular, residual and difference signals of one revolution of a gear with `teeth` teeth.
// InputError when the revolution holds fewer than 4·teeth samples (the first mesh order's
// sidebands need room below Nyquist) or teeth < 1.
TsaSignals tsa_signals(const std::vector<double>& tsa, int teeth);

struct ConditionIndicators {
  double rms = 0, crest_factor = 0, kurtosis = 0;
  double fm0 = 0, fm4 = 0, m6a = 0, na4 = 0, er = 0;
};

// Indicators of one revolution; FM4 and M6A are NaN when the difference signal is zero (a TSA of
// mesh orders, sidebands and shaft orders only), NA4 when the residual is. `residual_history` the residual signals of earlier records of the
// same gear (for NA4's mean variance; empty: NA4 = kurtosis of this residual).
ConditionIndicators condition_indicators(const std::vector<double>& tsa, int teeth,
                                         const std::vector<std::vector<double>>& residual_history = {});

// Sample statistics of a record (about its mean): RMS, crest factor, kurtosis, and the normalised
// sixth moment N² Σ(x − x̄)⁶ / (Σ(x − x̄)²)³. InputError on fewer than 2 samples or a constant record.
double rms_about_mean(const std::vector<double>& x);
double crest_factor(const std::vector<double>& x);
double kurtosis(const std::vector<double>& x);
double sixth_moment(const std::vector<double>& x);

}  // namespace gearsim
