#include "fe/planetary_fe.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <exception>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <mutex>
#include <numbers>
#include <thread>

#include "core/errors.hpp"
#include "fe/planetary_fe_detail.hpp"
#include "fe/process.hpp"
#include "core/output_file.hpp"

namespace gearsim::fe {
namespace planetary_detail {

const GearSpec& planet_gear(const PlanetaryFeDef& def, int k) {
  return def.planet_gears.empty() ? def.spec.planet : def.planet_gears[static_cast<size_t>(k)];
}

namespace {

// The tooth an error names, or -1.
int error_tooth(const GearErrors& e) {
  for (const auto& f : e.flank_offsets)
    if (f.normal_offset_m != 0) return f.tooth;
  for (const auto& f : e.profile_slopes)
    if (f.slope_m != 0 && f.tooth >= 0) return f.tooth;
  for (const auto& f : e.pitch_errors)
    if (f.error_m != 0) return f.tooth;
  return -1;
}

// ccx's run of the deck in work_dir (position.inp, .dat and .log), or the finished run of the
// very same deck already there (position.done holds its wall time).
CcxRunResult solved_or_reused(const PlanetaryFeDef& def, const Deck& d, const std::filesystem::path& work_dir) {
  std::filesystem::create_directories(work_dir);
  CcxRunResult run;
  run.dat_path = work_dir / "position.dat";
  run.log_path = work_dir / "position.log";
  bool reused = false;
  {
    std::ifstream old_deck(work_dir / "position.inp"), done(work_dir / "position.done");
    if (old_deck && done && std::filesystem::exists(run.dat_path)) {
      const std::string text((std::istreambuf_iterator<char>(old_deck)), std::istreambuf_iterator<char>());
      reused = text == d.text && static_cast<bool>(done >> run.wall_time_s);
    }
  }
  if (!reused) {
    std::filesystem::remove(work_dir / "position.done");
    write_output_file(work_dir / "position.inp", d.text);
    run = run_ccx({def.ccx, work_dir, "position"});
    write_output(work_dir / "position.done", [&](std::ostream& f) { f << std::setprecision(17) << run.wall_time_s << '\n'; });
  }
  return run;
}

}  // namespace
}  // namespace planetary_detail

TrackedTooth tracked_tooth(const PlanetaryFeDef& def) {
  for (int k = 0; k < static_cast<int>(def.planet_gears.size()); ++k) {
    const GearSpec& g = def.planet_gears[static_cast<size_t>(k)];
    const int t = planetary_detail::error_tooth(g.errors);
    if (t >= 0) return {k, t % g.teeth, true};
  }
  return {0, 0, false};
}

PlanetaryFeMeshes mesh_planetary(const PlanetaryFeDef& def) {
  if (!def.planet_gears.empty() && static_cast<int>(def.planet_gears.size()) != def.spec.planets)
    throw InputError("planetary FE: planet_gears must list one gear per planet (" + std::to_string(def.spec.planets) + ")");
  PlanetaryFeMeshes m;
  m.sun = mesh_gear_outline(make_gear_outline(def.spec.sun), GearKind::External, def.sizing);
  m.ring = mesh_gear_outline(make_gear_outline(def.spec.ring), GearKind::Internal, def.sizing);
  for (int k = 0; k < def.spec.planets; ++k)
    m.planets.push_back(mesh_gear_outline(make_gear_outline(planetary_detail::planet_gear(def, k)), GearKind::External, def.sizing));
  return m;
}

PlanetaryFePosition solve_position(const PlanetaryFeDef& def, const PlanetaryFeMeshes& meshes, double sun_turn_rad,
                                   const std::filesystem::path& work_dir) {
  using namespace planetary_detail;
  const PositionDeck p = build_position_deck(def, meshes, sun_turn_rad);
  // Solve, unless this folder already holds a finished solve of the very same deck (a resumed
  // run): position.done records the solve's wall time once ccx has succeeded.
  const CcxRunResult run = solved_or_reused(def, p.written, work_dir);
  return read_position(p, def, run, sun_turn_rad);
}

std::vector<double> sweep_turns(const PlanetaryFeDef& def, int positions_per_mesh, double mesh_periods) {
  if (positions_per_mesh < 1)
    throw InputError("planetary FE: positions_per_mesh must be at least 1, got " + std::to_string(positions_per_mesh));
  if (!(mesh_periods > 0) || !std::isfinite(mesh_periods))
    throw InputError("planetary FE: mesh_periods must be a positive number of mesh periods");
  const PlanetarySpec& ps = def.spec;
  const PlanetaryGeometry geo = analyse_planetary(ps);
  const double zs = ps.sun.teeth, zp = ps.planet.teeth;
  const TrackedTooth tracked = tracked_tooth(def);
  const PlanetPlacement& p0 = geo.placements.at(static_cast<size_t>(tracked.planet));
  // Planet 0 turns −φ z_s/z_p with the sun's turn φ; its tooth 0 faces the sun (polar angle
  // carrier_angle + π) once per planet revolution, i.e. every 2π z_p/z_s of φ.
  const double period = 2.0 * std::numbers::pi * zp / zs;
  // The flank the sun loads (sun driving counter-clockwise) passes the pitch point a quarter of a
  // mesh period later: half the tooth thickness at the pitch circle, π/(2 z_p) of planet turn,
  // is π/(2 z_s) of sun turn (checked with the rigid closing of a faulty tooth 0: its extra
  // closing spans +0.125…+0.375 of a mesh period after the centre-line passage).
  double centre = (p0.spin_angle_rad + planetary_detail::planet_gear(def, tracked.planet).tooth0_angle_rad +
                   tracked.tooth * 2.0 * std::numbers::pi / zp - p0.carrier_angle_rad - std::numbers::pi) *
                      zp / zs +
                  std::numbers::pi / (2.0 * zs);
  centre = std::fmod(centre, period);
  if (centre < 0) centre += period;
  const int n = std::max(1, static_cast<int>(std::lround(positions_per_mesh * mesh_periods)));
  const double step = 2.0 * std::numbers::pi / zs / positions_per_mesh;
  std::vector<double> turns;
  for (int j = 0; j < n; ++j) turns.push_back(centre + (j - 0.5 * n) * step);
  return turns;
}

std::vector<PlanetaryFePosition> solve_positions(const PlanetaryFeDef& def, const PlanetaryFeMeshes& meshes,
                                                 const std::vector<double>& turns_rad, const std::filesystem::path& work_dir, int jobs,
                                                 const std::function<void(std::size_t, const PlanetaryFePosition&)>& on_done) {
  if (jobs < 1) throw InputError("planetary FE: jobs must be at least 1, got " + std::to_string(jobs));
  std::vector<PlanetaryFePosition> out(turns_rad.size());
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr first_error;
  std::mutex mutex;
  auto worker = [&] {
    for (;;) {
      if (failed) return;
      const std::size_t i = next++;
      if (i >= turns_rad.size()) return;
      char name[32];
      std::snprintf(name, sizeof name, "pos_%03zu", i);
      try {
        PlanetaryFePosition p = solve_position(def, meshes, turns_rad[i], work_dir / name);
        std::lock_guard<std::mutex> lock(mutex);
        out[i] = p;
        if (on_done) on_done(i, out[i]);
      } catch (...) {
        std::lock_guard<std::mutex> lock(mutex);
        if (!first_error) first_error = std::current_exception();
        failed = true;
        return;
      }
    }
  };
  std::vector<std::thread> threads;
  const int n = std::min<int>(jobs, static_cast<int>(turns_rad.size()));
  for (int t = 0; t < n; ++t) threads.emplace_back(worker);
  for (auto& t : threads) t.join();
  if (first_error) std::rethrow_exception(first_error);
  return out;
}

}  // namespace gearsim::fe
