// The bounds every number from an input file or the command line is checked against before
// anything is allocated or run from it, each with its unit and why. A value outside is refused
// naming file:line:key (or the option) and the bound; NaN and infinity are always refused.
// Bounds are sanity limits far beyond any real gearbox run, not physics: the physical bounds of
// a running simulation are sim/run_bounds.hpp. Not a schema: each reader applies the limit
// of the key it reads.
#pragma once

#include <CLI/CLI.hpp>

#include <cstddef>
#include <numbers>
#include <string>

#include "input/yaml_reader.hpp"

namespace gearsim::input {

// A closed interval [min, max] in `unit`; an open end where min_open (max_open) says so.
struct Limit {
  double min;
  double max;
  bool min_open;
  const char* unit;  // "s", "Hz", "" for counts and factors
  const char* what;  // the message's noun: "a duration"
  bool max_open = false;
};

namespace limits {

// Scenario and gear-set files are a few kB (the largest in assets/ is 5 kB); yaml-cpp holds about
// 30× the text in memory (a 50 MB file peaked at 1.6 GB), so 4 MiB stays near 130 MB.
constexpr std::size_t kMaxYamlBytes = 4u << 20;
// Values in one YAML file, aliases counted each time they are met: a file of 4 MiB holds at most
// ~1e6 values; more means aliases multiplying a list ("billion laughs").
constexpr std::size_t kMaxYamlValues = 1'000'000;
// Nesting levels of one YAML file: the deepest scenario key path is 5 levels; every reader walks
// the tree recursively, so a bound keeps the stack small (an alias inside its own anchor,
// `&r [1, *r]`, is an endless nesting that this bound ends).
constexpr std::size_t kMaxYamlDepth = 64;
// A JSON record a command reads back from an output folder (scenario.json, summary.json,
// analysis.json, a sweep's case.json): the paper run's largest is ~60 kB; nlohmann's tree holds
// about 10× the text, so 64 MiB stays under 1 GB.
constexpr std::size_t kMaxRecordBytes = std::size_t{64} << 20;
// A run's CSV log read back whole (state.csv, contacts.csv, sensors.csv): the paper run writes
// ~1 MB per simulated second at its 10 kHz output rate; 4 GiB is over an hour of it, and about
// the memory its columns then take as numbers.
constexpr std::size_t kMaxCsvLogBytes = std::size_t{4} << 30;

// Simulated time, s: the paper's set costs ~4 s wall per simulated second at dt 2e-5 s, so 1e4 s
// is about 11 h and 5e8 steps; more is a typo (--duration 1e300 gave 0 steps).
constexpr Limit kDuration_s{0, 1e4, true, "s", "a duration"};
// Time step, s: below 1e-7 s a simulated second takes ~1e3 times the paper run's wall time; above
// 1e-2 s not even the mesh frequency of a slow train (~100 Hz) is resolved.
constexpr Limit kTimeStep_s{1e-7, 1e-2, false, "s", "a time step"};
// Constraint solver iterations per step: 2000× the default 50; each is a sweep over every constraint.
constexpr Limit kSolverIterations{1, 1e5, false, "", "a number of solver iterations"};
// θ of the multibody engine's θ-method: below ½ it is unstable for stiff springs, 1 is implicit Euler.
constexpr Limit kSolverTheta{0.5, 1, false, "", "a θ-method weight"};
// Motor and load ramps, s: no longer than the longest run (kDuration_s).
constexpr Limit kRampTime_s{0, 1e4, false, "s", "a ramp time"};
// Render slow motion: 1000× shows 1 ms of the run as 1 s of video; frames = duration·fps·slowmo.
constexpr Limit kSlowMotion{0, 1000, true, "", "a slow-motion factor"};
// Times within a run (render and analysis windows), s: within the longest run.
constexpr Limit kRunTime_s{0, 1e4, false, "s", "a time"};
// Planets of a planetary train: each is a body, a hinge and two meshes allocated before the
// assembly check; 64 equally spaced planets already need over 200 teeth on the sun.
constexpr Limit kPlanets{1, 64, false, "", "a number of planets"};
// Teeth of a gear or of a mesh's tooth layout: 3 is the fewest an involute gear can have; a
// 1000-tooth outline at the default 0.5 µm chordal deviation is ~1e6 points, beyond any gearbox.
constexpr Limit kTeeth{3, 1000, false, "", "a number of teeth"};
// Chordal deviation of gear outlines, m: below 1 nm the outline is millions of points per tooth;
// above 0.1 mm a 1 mm module tooth (2.25 mm high) is a few segments and its flanks are lost.
constexpr Limit kChordalDeviation_m{1e-9, 1e-4, false, "m", "a chordal deviation"};

// Gear geometry (gear-set specs, a scenario's `gear:`, run records). Each bound keeps the outline
// finite: 1e300 m overflows the tessellation (an internal error, not a refusal).
// Module, m: 0.01 mm is below the finest watch gears' (~0.05 mm); 0.1 m is twice the largest
// mill gears' (~50 mm).
constexpr Limit kModule_m{1e-5, 0.1, false, "m", "a module"};
// Face width, m: 0.01 mm is a foil; 2 m is twice the widest mill and wind-turbine gears' faces.
constexpr Limit kFaceWidth_m{1e-5, 2, false, "m", "a face width"};
// Pressure angle, rad: the involute needs 0 < α < 45° (gear_dimensions.cpp); real spur gears
// use 14.5° to 25°. Keys in degrees are checked against it in degrees (limit_in_degrees).
constexpr Limit kPressureAngle_rad{0, std::numbers::pi / 4, true, "rad", "a pressure angle", true};
// Helix angle on the reference circle, rad: 0 (spur) up to 45°; industrial helical gears use
// 7°–30°, double-helical ones up to 45°.
constexpr Limit kHelixAngle_rad{0, std::numbers::pi / 4, false, "rad", "a helix angle"};
// Profile shift coefficient x, in modules: practical shifts lie within −1 to +1.5; beyond ±3 a
// tooth is all root or all tip.
constexpr Limit kProfileShift{-3, 3, false, "", "a profile shift coefficient (in modules)"};
// Addendum and dedendum factors h_a*, h_f*, in modules: the basic rack's are 1 and 1.25; 3 is
// over twice the deepest high-addendum teeth's.
constexpr Limit kToothDepthFactor{0, 3, false, "", "a tooth depth factor (in modules)"};
// Root fillet radius factor ρ*, in modules: ISO 53's racks use 0.25 to 0.38; 1 is a full round
// root on a deep tooth.
constexpr Limit kRootFilletFactor{0, 1, false, "", "a root fillet factor (in modules)"};
// Backlash allowance (thinning) per flank, m: a 10 mm module gear's is ~0.1 mm; 1 mm is ten times
// that.
constexpr Limit kThinning_m{0, 1e-3, false, "m", "a thinning per flank"};
// Flank, pitch and profile slope errors, m (either sign): DIN 3962 class 12 (the coarsest) allows
// ~0.1 mm at a 10 mm module; 1 mm is ten times that.
constexpr Limit kToothError_m{-1e-3, 1e-3, false, "m", "a tooth error"};
// Eccentricity of a toothing, m: radial runout is twice it; a class-12 gear of 1 m diameter allows
// ~0.3 mm runout, 10 mm is thirty times that.
constexpr Limit kEccentricity_m{0, 1e-2, false, "m", "an eccentricity"};
// Bore and rim diameters, m: a gear at the largest module and tooth count (0.1 m × 1000) is 100 m
// across.
constexpr Limit kGearDiameter_m{0, 100, false, "m", "a diameter"};
// Angles of a pose or of tooth 0, rad: one turn either way; more names the same pose and is most
// likely degrees given as radians. In degrees: ±360°.
constexpr Limit kAngle_rad{-2 * std::numbers::pi, 2 * std::numbers::pi, false, "rad", "an angle"};
// Quality class of a gear's tolerances: ISO 1328-1 has classes 0 to 12, DIN 3961 1 to 12.
constexpr Limit kQualityClass{0, 12, false, "", "a quality class"};
// Centre distance of two gears, m: positive (no other value means "derive it": leave the key
// out); 100 m is two of the largest gears side by side.
constexpr Limit kCentreDistance_m{0, 100, true, "m", "a centre distance"};
// Body positions, hinge pivots and macro origins, m: 1 km from the origin is far beyond any
// gearbox, and doubles there still resolve 1e-13 m, well below a tooth contact's nanometres.
constexpr Limit kPosition_m{-1e3, 1e3, false, "m", "a coordinate"};

// The finite-element model of fe-te (a scenario's fe:), m. Element sizes: 10 µm puts ~1e7 quads on
// a 1 mm module planetary set; 0.1 m is a large gear in one element. The size transition: up to
// 1 m, a large gear's radius. The boundary's sagitta: 0 (none) to 1 mm, a coarse module's tooth.
constexpr Limit kFeElementSize_m{1e-5, 0.1, false, "m", "an element size"};
constexpr Limit kFeTransition_m{0, 1, false, "m", "a size transition"};
constexpr Limit kFeSagitta_m{0, 1e-3, false, "m", "a sagitta"};

// Mass properties (bodies, the planetary carrier, inspect --density).
// Density, kg/m³: 1 is below an aerogel's, 1e5 over four times osmium's (22 590); steel is 7850.
constexpr Limit kDensity_kg_m3{1, 1e5, false, "kg/m³", "a density"};
// Mass, kg: 1 µg is a grain of dust; 1e6 kg is ten times the heaviest mill ring gear (~100 t).
constexpr Limit kMass_kg{1e-9, 1e6, false, "kg", "a mass"};
// Principal moment of inertia, kg·m²: 1e-18 is 1 µg at 1 µm; 1e9 is 1e6 kg at a 30 m radius.
constexpr Limit kInertia_kg_m2{1e-18, 1e9, false, "kg·m²", "a moment of inertia"};

// Drives, loads, contact and supports: the physics a run is set up with. Each bound sits where a
// value beyond it would leave the run's own physical bounds (sim/run_bounds.hpp) at the first steps
// or is beyond any gearbox built.
// Motor target speed, rad/s (either sense): a run stops as diverged above 2e4 rad/s (RunBoundsDef).
constexpr Limit kMotorSpeed_rad_s{-2e4, 2e4, false, "rad/s", "a motor speed"};
// Torques, N·m (either sense): a 15 MW wind turbine's main shaft carries ~2e7 N·m; 1e8 is five
// times that.
constexpr Limit kTorque_N_m{-1e8, 1e8, false, "N·m", "a torque"};
// A motor's torque limit, N·m: positive, up to the largest torque (kTorque_N_m).
constexpr Limit kMaxTorque_N_m{0, 1e8, true, "N·m", "a torque limit"};
// Viscous load coefficient, N·m·s/rad: 1e8 opposes the largest torque at 1 rad/s.
constexpr Limit kViscous_N_m_s_per_rad{0, 1e8, false, "N·m·s/rad", "a viscous coefficient"};
// Impulse forces, N (each component, either sense): 1e9 N is far past any blow a gearbox takes.
constexpr Limit kImpulseForce_N{-1e9, 1e9, false, "N", "a force component"};
// Tooth contact stiffness per metre of face, N/m per m: ISO 6336's c' for steel is ~1.4e10; 1e13
// is 700 times that (an ever stiffer spring only shortens the stable step).
constexpr Limit kContactStiffness_N_per_m_per_m{0, 1e13, true, "N/m per m", "a contact stiffness"};
// Stiffnesses of a whole mesh or gear body, and radial bearing stiffness, N/m: a large roller
// bearing or mesh is 1e9–1e10 N/m; 1e13 is a thousand times that.
constexpr Limit kStiffness_N_per_m{0, 1e13, true, "N/m", "a stiffness"};
// Translational damping, N·s/m: critical damping of 1e6 kg on 1e13 N/m is ~6e9.
constexpr Limit kDamping_N_s_per_m{0, 1e10, false, "N·s/m", "a damping"};
// Torsional support stiffness, N·m/rad (0: free to turn): a 1 m steel shaft of 1 m diameter is ~8e9.
constexpr Limit kTorsionalStiffness_N_m_per_rad{0, 1e12, false, "N·m/rad", "a torsional stiffness"};
// Torsional damping, N·m·s/rad.
constexpr Limit kTorsionalDamping_N_m_s_per_rad{0, 1e10, false, "N·m·s/rad", "a torsional damping"};
// A shaft's length between the members it joins, m: a coupling's few mm to a wind turbine's
// main shaft (a few m).
constexpr Limit kShaftLength_m{0, 100, false, "m", "a shaft length"};
// Shear modulus of a shaft's material, Pa: polymers (~1 GPa) to tungsten carbide (~270 GPa).
constexpr Limit kShearModulus_Pa{1e8, 1e12, false, "Pa", "a shear modulus"};
// Damping ratios ζ: 1 is critical; 10 stops any vibration within a fraction of a period.
constexpr Limit kDampingRatio{0, 10, false, "", "a damping ratio"};
// Coulomb friction coefficient: dry steel on steel is 0.6–0.8; 2 is past any metal pair.
constexpr Limit kFriction{0, 2, false, "", "a friction coefficient"};
// How far a contact may lie off a tabulated flank and still count, m: a module-1 tooth is 2.25 mm
// high; 10 mm is past any tooth's own height at module 4.
constexpr Limit kFlankDeparture_m{0, 1e-2, true, "m", "a flank departure"};
// A transmission's nominal ratio θ_input/θ_output, in magnitude (either sign, never 0): 1e6 is
// past any train of gears.
constexpr Limit kRatioMagnitude{1e-6, 1e6, false, "", "a ratio's magnitude"};
// A sensor's path gain of the other meshes, relative to the nearest (1 = as loud).
constexpr Limit kPathGain{0, 100, false, "", "a path gain"};
// Measurement noise rms, m/s²: 1e6 m/s² is 1e5 g.
constexpr Limit kNoise_m_s2{0, 1e6, false, "m/s²", "a noise rms"};

// Rates and frequencies a run records, Hz (output and filter rates, band edges): none exceeds the
// step rate at the shortest time step, 1/kTimeStep_s.min = 1e7 Hz.
constexpr Limit kRate_Hz{0, 1e7, true, "Hz", "a rate"};

// Options of the commands (and the Python module's keywords of the same name).
// Mesh harmonics of a Campbell table (modes --harmonics): beyond 50 the crossings lie far above
// any mode the lumped model resolves.
constexpr Limit kModeHarmonics{1, 50, false, "", "a number of mesh harmonics"};
// Mesh positions per pitch for the mean mesh stiffness (modes --phases): 4 is the coarsest that
// sees the double-contact zone; 4096 resolves it far below the flank table's own error.
constexpr Limit kModePhases{4, 4096, false, "", "a number of mesh positions per pitch"};
// A drive speed cap, rad/s (modes --max-speed): high-speed turbine gears turn at ~3000 rad/s;
// 1e5 rad/s is thirty times that.
constexpr Limit kDriveSpeed_rad_s{0, 1e5, true, "rad/s", "a drive speed"};
// How far a mesh's vertices may lie off its cap planes and still make a prism, µm (inspect
// --prism-tolerance): CAD noise is ~1 µm; at 1 mm the mesh is another shape.
constexpr Limit kPrismTolerance_um{0, 1000, true, "µm", "a prism tolerance"};
// Sample spacing of a deviation measurement, mm (--hausdorff-spacing): 0.01 mm puts ~1e7 samples
// on a 100 mm gear's faces; 100 mm samples only the vertices of any gear.
constexpr Limit kSampleSpacing_mm{0.01, 100, false, "mm", "a sample spacing"};
// Rendered frame width and height, px (render --width/--height): 16 px shows nothing smaller;
// 4096 px is a 4K frame, the largest an H.264 level-5.1 encoder takes.
constexpr Limit kFrameSize_px{16, 4096, false, "px", "a frame size"};
// Processes run at once (sweep --jobs): far beyond the cores of one machine.
constexpr Limit kJobs{1, 1024, false, "", "a number of jobs"};

// Cases of one parameter sweep (grid product or list): each is a run folder and a process; 1e5
// runs of the shortest useful case (~1 s) are a day on 2 cores, more is a typo in a grid.
constexpr std::size_t kMaxSweepCases = 100'000;
// Values of one grid axis ({from, to, steps}): as many as a sweep may have cases.
constexpr Limit kSweepSteps{2, 1e5, false, "", "a number of grid steps"};

}  // namespace limits

// True for a finite value inside the limit.
bool within(double value, const Limit& limit);
// "expected a duration in (0, 10000] s, got 1e+300".
std::string limit_message(const Limit& limit, double value);
// InputError "<name>: <limit_message>" unless `value` is within the limit: the check of a named
// argument (a Python keyword) with the message the CLI gives for the same option.
void require_within(const std::string& name, double value, const Limit& limit);
// An angle's limit in degrees (unit "°"), for keys and options given in degrees.
Limit limit_in_degrees(const Limit& limit_rad);

// m[key] as a number within `limit`, else m.fail(key, limit_message(…)).
double number_within(const YamlMap& m, const std::string& key, const Limit& limit);
// The same with a fallback when the key is absent (the fallback is not checked).
double number_within_or(const YamlMap& m, const std::string& key, double fallback, const Limit& limit);
// m[key] as an integer within `limit` (checked before any narrowing).
int integer_within(const YamlMap& m, const std::string& key, const Limit& limit);
int integer_within_or(const YamlMap& m, const std::string& key, int fallback, const Limit& limit);

// A CLI11 check of an option's value against `limit` (NaN, inf and text refused).
CLI::Validator cli_within(const Limit& limit);

}  // namespace gearsim::input
