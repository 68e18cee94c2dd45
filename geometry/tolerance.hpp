// Gear accuracy tolerances: allowable deviations of a cylindrical gear for a quality class, after
// DIN 3961/3962 and ISO 1328-1:1995. Two formula sets:
//  - the paper's equations (1)-(5) (reference 000, section 3: f_f, f_Hα, F_p, F_α and the
//    single-flank composite F_i' = 0.8 (F_p + F_α)), graded with either standard's class step;
//  - ISO 1328-1:1995's own class-5 formulas (§6, Annex A and B), graded with the ISO step.
// Not a table lookup: every value is the class-5 formula at the gear's own m_n, d and z, not at
// the geometric mean of a standard's size range as the printed tables are, so a value can differ
// from the printed table by up to ~15 % near a range edge. Helix (lead) tolerances: not covered.
//
// UNITS: not SI, on purpose. The standards define these formulas with the module and diameter in
// mm and the result in µm, and their rounding rules are in µm; every name carries its unit
// (`_mm`, `_um`). Convert to metres (× 1e-6) where a tolerance enters the simulation.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gearsim {

enum class ToleranceStandard {
  Din3961,  // DIN 3961/3962 (1978): 12 classes, step 1.4 per class
  Iso1328,  // ISO 1328-1:1995: 13 classes (0-12), step √2 per class
};

// Class steps, relative to class 5 (where both standards state their formulas).
// DIN 3961: tolerances grow by 1.4 per class (DIN 3963's F_i' table, m_n 1-2 mm, reads 18, 25,
// 36, 50, 71, 100 µm for classes 7-12).
inline constexpr double kDinClassStep = 1.4;
// ISO 1328-1:1995 §6: adjacent classes differ by √2, so class Q is 2^((Q − 5)/2) × class 5.

// Validity ranges; out-of-range input is an InputError, never clamped.
inline constexpr int kDinMinQuality = 1;
inline constexpr int kDinMaxQuality = 12;
inline constexpr int kIsoMinQuality = 0;
inline constexpr int kIsoMaxQuality = 12;
inline constexpr double kIsoMinModule_mm = 0.5;
inline constexpr double kIsoMaxModule_mm = 70.0;
inline constexpr double kIsoMinDiameter_mm = 5.0;
inline constexpr double kIsoMaxDiameter_mm = 10000.0;
// Total contact ratio below 1: the pair does not mesh continuously; not a working gear pair.
inline constexpr double kMinContactRatio = 1.0;

// One gear and the class asked for.
struct ToleranceInput {
  double module_mm = 0.0;  // normal module m_n, mm
  int teeth = 0;  // number of teeth z (≥ 1)
  double reference_diameter_mm = 0.0;  // reference diameter d = z·m_n/cos β, mm
  int quality = 0;  // quality class (DIN 1-12, ISO 0-12)
  // Total contact ratio ε_γ of the mesh, dimensionless. Only ISO 1328-1 Annex A (f_i', F_i')
  // needs it; without it those two are left out, never guessed.
  std::optional<double> contact_ratio;
};

// One allowable deviation, with every step from the class-5 formula to the tabulated value.
struct ToleranceComponent {
  std::string key;  // stable identifier, e.g. "total_pitch" (JSON: "total_pitch_um")
  std::string symbol;  // e.g. "F_p"
  std::string name;  // e.g. "total cumulative pitch deviation"
  std::string formula;  // the class-5 formula, m and d in mm, result in µm
  double class5_um = 0.0;  // the formula's value (class 5), µm
  double unrounded_um = 0.0;  // class5_um × step factor, µm
  double value_um = 0.0;  // unrounded_um rounded by the standard's rule, µm
};

// The tolerances of one gear at one class under one standard.
struct ToleranceResult {
  ToleranceStandard standard = ToleranceStandard::Din3961;
  std::string formula_set;  // which formulas gave the class-5 values
  int quality = 0;
  double step_factor = 1.0;  // class-5 → `quality` multiplier, dimensionless
  std::vector<ToleranceComponent> components;
  // Single-flank composite tolerance F_i' (rounded), µm: the paper's "single flank error".
  // Always set for the paper set; for the ISO set only when a contact ratio was given.
  std::optional<double> single_flank_error_um;
  // ISO 1328-1 Annex A factor K of f_i' (dimensionless); set when f_i' is.
  std::optional<double> composite_k;

  // The component with this key, or nullptr.
  const ToleranceComponent* find(std::string_view key) const;
  // The component with this key; a missing key is a bug in the caller (InternalError).
  const ToleranceComponent& at(std::string_view key) const;
};

// The paper's equations (1)-(5), graded by `standard`'s class step and rounding.
// Rounding order: every reported value is rounded once, from its own unrounded value, as ISO
// tabulates each quantity from its own formula; F_α (eq 4) and F_i' (eq 5) combine the unrounded
// class-5 values. Both equations are homogeneous of degree 1, so combining then scaling equals
// scaling then combining; only the rounding order matters (ISO class 8 here: 44 µm this way,
// 45 µm if the rounded components were combined).
// Throws InputError naming the parameter, its value and the expected range.
ToleranceResult paper_tolerances(const ToleranceInput& in, ToleranceStandard standard);

// ISO 1328-1:1995's own class-5 formulas, graded by the ISO step and rounding.
// Throws InputError naming the parameter, its value and the expected range.
ToleranceResult iso1328_tolerances(const ToleranceInput& in);

// Multiplier from class 5 to `quality`: DIN 1.4^(Q−5), ISO 2^((Q−5)/2). Unchecked range.
double class_step_factor(ToleranceStandard standard, int quality);

// A tolerance rounded as the standard tabulates it, µm.
//  ISO 1328-1:1995: above 10 µm to 1 µm; 5 µm to 10 µm to 0.5 µm; below 5 µm to 0.1 µm.
//  DIN 3962 (our reading of its tables): 10 µm and above to 1 µm; below 10 µm to 0.5 µm.
// Halves round away from zero (7.25 → 7.5).
double round_tolerance_um(ToleranceStandard standard, double value_um);

// Display and machine names: "DIN 3961/3962" / "din3961", "ISO 1328-1:1995" / "iso1328".
std::string_view standard_name(ToleranceStandard standard);
std::string_view standard_key(ToleranceStandard standard);
// The step and rounding rules as text, for reports.
std::string_view step_rule(ToleranceStandard standard);
std::string_view rounding_rule(ToleranceStandard standard);

}  // namespace gearsim
