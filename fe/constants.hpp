// Constants of the flexible-teeth (finite element) work, each with its unit and why.
// Not the rigid-body contact constants (those live with physics/).
#pragma once

namespace gearsim::fe {

// Steel, the gears' material (paper and ISO 6336 reference material).
inline constexpr double kYoungModulus_Pa = 210e9;  // normally 210 GPa
inline constexpr double kPoissonRatio = 0.3;  // normally 0.3

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

// Potential-energy (analytical) mesh stiffness, fe/potential_energy.hpp.
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

// ---- Quadrilateral meshes of gear outlines (gear_mesher.hpp) ----

// Element size along flanks and root fillets, m. Normally 0.4 mm: the paper's converged size for
// module 1 mm teeth.
inline constexpr double kDefaultFlankElementSize_m = 0.4e-3;
// Flank element size of a loaded-TE run (gearsim fe-te) unless the scenario gives one, m. 0.2 mm:
// the element-size study of the paper's gearbox (docs/fe-results.md) moves the elastic TE by 2.1 % from
// 0.2 to 0.1 mm, but by 19 % from 0.4 to 0.2 mm (module 1 mm; about m/5).
inline constexpr double kDefaultFeTeFlankSize_m = 0.2e-3;
// Element size in the gear body away from the teeth, m. Normally 2 mm (five flank sizes): the
// body only carries the tooth loads to the bore or rim.
inline constexpr double kDefaultCoreElementSize_m = 2.0e-3;
// Distance over which the size grows from the flank size at the root circle to the core size,
// inward (external gears) or outward (internal gears), m. Normally 3 mm (three modules): the
// bending stresses of a tooth fade within about a tooth height below its root.
inline constexpr double kDefaultSizeTransition_m = 3.0e-3;

// An outline vertex that turns the boundary by more than this is kept as a mesh node (a corner),
// rad. Normally 30°: a tooth tip corner turns 61°–73° on the paper's gears (90° less the tip
// pressure angle), while every other vertex of their outlines (0.5 µm chordal deviation) turns
// ≤ 5.3° (root fillets, ρ = 0.38 mm, are the sharpest curves).
inline constexpr double kOutlineCornerTurn_rad = 0.5235987755982988;
// A boundary node placed by arc length moves onto the nearest outline vertex when that vertex is
// within this fraction of the local spacing: vertices lie exactly on the true curve, points
// between them only within the outline's chordal deviation. Normally 0.2 (spacing varies ±20 %).
inline constexpr double kSnapToVertexFraction = 0.2;
// Largest distance of a straight mesh edge on the toothed loop from the true outline, m. Normally
// 5 µm. A chord across a curve moves the FE boundary by up to its sagitta c²/(8ρ): at 0.4 mm
// edges 5 µm on the paper's sun flank (ρ ≈ 4 mm) and 50 µm across a 0.38 mm root fillet — on an
// internal gear that chord lies in the tooth space where the mate's tip passes, and the planet–
// ring pair of the paper's set overlapped by ~6 µm where the exact outlines touch. 5 µm makes
// fillet edges ~0.12 mm and doubles the quad count (sun 1126 → 2148, ring 5044 → 10336 at
// 0.4 mm); 0.5 µm, the outline's own tolerance, would make 5–7× more quads. The flank chords'
// remaining few µm are a geometric error, not an elastic one: planetary_fe takes the geometric
// transmission error from the exact outlines and only the load-dependent part from the FE.
inline constexpr double kDefaultMaxSagitta_m = 5e-6;
// How fast the boundary spacing may change along the outline, m of spacing per m of arc
// (normally 0.3: neighbouring edges differ by at most ~30 %, so the quads beside them stay well
// shaped).
inline constexpr double kSpacingGrading = 0.3;
// gmsh 2D algorithm: 5 = Delaunay. Normally 5: recombined, its triangles gave the best quads on
// the paper's gears (min scaled Jacobian 0.60–0.62 at 0.4 mm, against 0.44–0.58 for 6,
// Frontal-Delaunay); Debian's gmsh 4.8.4 crashes with 8 (Frontal-Delaunay for quads) even on a
// unit square (segfault in backgroundMesh::getAngle).
inline constexpr int kGmshAlgorithm2D = 5;
// gmsh recombination: 1 = Blossom (a perfect matching of triangles into quads). Normally 1: with
// an even number of boundary edges on every loop it leaves no triangle.
inline constexpr int kGmshRecombination = 1;
// Laplacian smoothing sweeps over the interior nodes after a subdivision. Normally 5: enough to
// even out the quads beside boundary midpoints moved onto a fillet, few enough to keep the
// grading.
inline constexpr int kSubdivisionSmoothingSweeps = 5;
// Largest quad count a mesh may have before it is refused as a sizing mistake. Normally 2e6
// (a 0.01 mm flank size on the ring): beyond that gmsh runs for minutes and ccx for hours.
inline constexpr double kMaxQuadCount = 2e6;

}  // namespace gearsim::fe

namespace gearsim::fe {

// Deck units: ccx is unit-free; the decks use mm, N, MPa (contact search tolerances and penalty
// values are tuned for geometry of order 1–100).
inline constexpr double kDeckLength_per_m = 1e3;  // m → mm
inline constexpr double kDeckStress_per_Pa = 1e-6;  // Pa → MPa
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

namespace gearsim::fe {

// Planetary FE positions: the low load stage (fraction of the torque) for the secant stiffness,
// the press the closing step imposes on the sun's contacts (0.05 µm along the line of action),
// the idlers' weak rotational spring (N·m/rad; a planet turns ~1e-4 rad under load, so the spring
// takes ~1e-4 N·m against a ~2 N·m mesh torque on the planet: 5e-5 of it), and the
// contact search band beyond a partner's tip circle, in modules.
inline constexpr double kLowLoadFraction = 0.1;
inline constexpr double kClosingPress_m = 0.05e-6;
inline constexpr double kIdlerSpring_N_m_per_rad = 1.0;
inline constexpr double kContactBand_modules = 1.0;

}  // namespace gearsim::fe

// ---- gearsim fe-te defaults (the scenario's fe: section) ----
namespace gearsim::fe {
// Flank Coulomb friction of the FE contact pairs (the paper's 0.03).
inline constexpr double kDefaultFlankFriction = 0.03;
// Quasi-static positions per mesh period (normally 8: the 1↔2 pair changes at ε_α ≈ 1.65 fall
// 0.35 and 0.65 of a period apart, so each single- and double-pair zone gets 2–5 positions).
inline constexpr int kDefaultPositionsPerMesh = 8;
// ccx processes solving positions at once (normally 2: the reference machine's cores; each ccx
// runs single-threaded).
inline constexpr int kDefaultFeJobs = 2;

// Spur pair FE stiffness (spur_pair_fe.hpp).
// Bore diameter over root diameter of both gears, dimensionless. Normally 0.5: Sainsot's
// h_f = r_f / r_bore = 2, the potential-energy model's default body, inside the range of its fit.
inline constexpr double kSpurBoreOverRoot = 0.5;
// Pinion teeth given a contact pair: those whose driving flank meets the line of action within
// this many base pitches beyond either end of the path of contact. Normally 0.5: a tooth entering
// or leaving is caught (corner contact under load), the next one lies a whole pitch away.
inline constexpr double kSpurSlotMargin_basePitches = 0.5;
// A tooth pair "carries load" when its contact force exceeds this share of the total, dimensionless.
// Normally 0.02: the open pairs' tension (kOpenContactTension_Pa over a flank, ~0.1 N) stays far
// below it at any sensible load (2 % of 1000 N is 20 N).
inline constexpr double kLoadedPairShare = 0.02;
// Rotational spring on the driving pinion, N·m/rad. Normally 100: ~1 % of the mesh's torsional
// stiffness at a module-1 pinion (k r_b1² ≈ 1.3e8 N/m · (9.4 mm)² ≈ 1.1e4 N·m/rad), so when the
// contact is still open at the first iterations of a torque step (ccx sees a node touching an edge
// only once its faces overlap) the pinion turns ~1e-3 rad instead of being free; the spring's
// torque (100 N·m/rad · θ) is known exactly and taken off the applied torque.
inline constexpr double kSpurPinionSpring_N_m_per_rad = 100.0;
// Slack on the ends of the path of contact for a requested roll length, m (normally 1e-9 m: a
// roll length computed from the path's own ends may round by ~1e-18 m; 1 nm is still far below
// any element).
inline constexpr double kSpurRollSlack_m = 1e-9;

}  // namespace gearsim::fe
