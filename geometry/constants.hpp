// Every tolerance and default of the geometry library, written once with its unit and why.
#pragma once

#include <limits>
#include <numbers>

namespace gearsim::constants {

// π and the degree conversions, once (sources say `using gearsim::constants::kPi;` rather than
// defining their own, so that a unity build may compile several of them as one unit).
inline constexpr double kPi = std::numbers::pi;
inline constexpr double kTwoPi = 2.0 * std::numbers::pi;
inline constexpr double kRadPerDeg = std::numbers::pi / 180.0;
inline constexpr double kDegPerRad = 180.0 / std::numbers::pi;
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Largest distance between a tessellated curve and its chord, m. Normally 0.5 µm: the errors we
// model are tens of µm (the paper's single flank error is 43 µm), so 0.5 µm keeps them two
// orders of magnitude above the tessellation.
inline constexpr double kDefaultChordalDeviation_m = 0.5e-6;

// Smallest chordal deviation a spec may ask for, m: below ~1 nm doubles at gear scale (0.1 m)
// leave too few significant digits for the curve evaluation itself.
inline constexpr double kMinChordalDeviation_m = 1e-9;

// Deepest recursion of the adaptive curve subdivision; 2^24 segments is far past any sane curve.
inline constexpr int kMaxSubdivisionDepth = 24;

// Standard basic rack (ISO 53 profile A): addendum, dedendum and root-fillet radius, in modules.
inline constexpr double kAddendumCoeff = 1.0;
inline constexpr double kDedendumCoeff = 1.25;
inline constexpr double kRootFilletCoeff = 0.38;

// Default pressure angle, rad (20°).
inline constexpr double kDefaultPressureAngle_rad = 20.0 * std::numbers::pi / 180.0;

// Steel density used by the paper (Table 2: 7.58e-9 t/mm³), kg/m³.
inline constexpr double kPaperSteelDensity_kg_m3 = 7580.0;

}  // namespace gearsim::constants
