// Constants of the flexible-teeth (finite element) work, each with its unit and why.
// Not the rigid-body contact constants (those live with physics/).
#pragma once

namespace gearsim::fe {

// Steel, the gears' material (paper and ISO 6336 reference material).
inline constexpr double kYoungModulus_Pa = 210e9;   // normally 210 GPa
inline constexpr double kPoissonRatio = 0.3;        // normally 0.3

// ISO 6336-1:2019 eq. (74)–(76), method B: theoretical single-tooth stiffness coefficients,
// 1/q' = c'_th with q' in mm·µm/N.
inline constexpr double kIsoC1 = 0.04723;
inline constexpr double kIsoC2 = 0.15551;
inline constexpr double kIsoC3 = 0.25791;
inline constexpr double kIsoC4 = -0.00635;
inline constexpr double kIsoC5 = -0.11654;
inline constexpr double kIsoC6 = -0.00193;
inline constexpr double kIsoC7 = -0.24188;
inline constexpr double kIsoC8 = 0.00529;
inline constexpr double kIsoC9 = 0.00182;
// Correction factor C_M between theory and measurement (ISO 6336-1, normally 0.8).
inline constexpr double kIsoCorrectionCM = 0.8;
// Gear blank factor C_R for solid blanks (ISO 6336-1, 1.0).
inline constexpr double kIsoBlankCR = 1.0;
// Conversion of ISO's N/(mm·µm) to SI N/m² (stiffness per face width): 1 N/(mm·µm) = 1e9 N/m².
inline constexpr double kNPerMmUm_in_NPerM2 = 1e9;

// Potential-energy (analytical) mesh stiffness, physics/fe/potential_energy.hpp.
// Timoshenko shear coefficient of a rectangular tooth section (Yang & Lin 1987, normally 1.2).
inline constexpr double kPeShearCoefficient = 1.2;
// Sainsot et al. (2004) fillet-foundation fit: the body's r_f / r_int ratio h_f when the bore is
// not known, dimensionless (normally 2: a bore of half the root diameter, inside the fit's range).
inline constexpr double kPeDefaultRootOverBore = 2.0;
// Composite Gauss–Legendre quadrature of the tooth energy integrals: panels per segment
// (normally 24; 5 points each, so the integrals converge to ~1e-10 relative).
inline constexpr int kPeQuadraturePanels = 24;
// Most tooth pairs a sample can hold (contact ratio < 3).
inline constexpr int kPeMaxPairsInContact = 3;
// Slack when a contact point lies on the end of the path of contact, in m of roll length
// (normally 1e-12 m: rounding of the roll arithmetic, far below any geometric length).
inline constexpr double kPeRollSlack_m = 1e-12;

// ccx subprocess: longest log tail quoted in an error message (characters).
inline constexpr int kLogTailChars = 2000;

}  // namespace gearsim::fe

namespace gearsim::fe {

// Deck units: ccx is unit-free; the decks use mm, N, MPa (contact search tolerances and penalty
// values are tuned for geometry of order 1–100).
inline constexpr double kDeckLength_per_m = 1e3;   // m → mm
inline constexpr double kDeckStress_per_Pa = 1e-6; // Pa → MPa
// Contact pressure of an open contact at large clearance ("σ∞" of ccx's linear pressure-
// overclosure law): a small tension keeps open pairs from leaving free rigid-body modes.
// 0.1 MPa is 1e-4 of a flank's Hertzian pressure (~1 GPa).
inline constexpr double kOpenContactTension_Pa = 1e5;
// Static step incrementation: initial and largest increment (fractions of the step), smallest
// before ccx gives up, and the increment budget per step.
inline constexpr double kFirstIncrement = 0.1;
inline constexpr double kMaxIncrement = 0.25;
inline constexpr double kMinIncrement = 1e-5;
inline constexpr int kStepMaxIncrements = 1000;

}  // namespace gearsim::fe

namespace gearsim::fe {

// Closing the clearances of a quasi-static position: search step and range of the rotation that
// brings a flank into touch, and the bisection tolerance (1e-10 rad is 2 pm on a 20 mm radius).
inline constexpr double kClosingStep_rad = 1e-4;
inline constexpr double kMaxClosingTurn_rad = 0.05;
inline constexpr double kClosingTolerance_rad = 1e-10;
// Flank-table radial samples (as the dynamics uses: ~0.5 µm per sample at m = 1 mm).
inline constexpr int kFlankTableSamples = 4096;

}  // namespace gearsim::fe
