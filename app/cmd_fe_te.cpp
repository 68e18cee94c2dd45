// gearsim fe-te SCENARIO --out DIR: the quasi-static loaded transmission error of a planetary
// train by finite elements (Gmsh meshes of the gear outlines, one CalculiX solve per position),
// after the paper's section 6. Writes te_loaded.csv, mesh_stiffness.csv, summary.json and SVG
// plots in DIR, each ccx deck, log and result under DIR/ccx/pos_NNN. A failed solve ends the run
// with ccx's message and log path; the positions solved before it stay in the CSV files, and
// running the same command again reuses every position whose deck is unchanged (a resume).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <numeric>

#include "app/commands.hpp"
#include "app/exit_codes.hpp"
#include "app/gnuplot.hpp"
#include "app/output_folder.hpp"
#include "app/run_dir.hpp"
#include "input/scenario_file.hpp"
#include "core/errors.hpp"
#include "geometry/gear_dimensions.hpp"
#include "geometry/gear_mesh.hpp"
#include "fe/planetary_fe.hpp"
#include "fe/process.hpp"
#include "core/output_file.hpp"

namespace gearsim::app {
namespace {

using json = nlohmann::ordered_json;
namespace fs = std::filesystem;

struct FeTeOptions {
  std::string scenario;
  std::string out_dir;
  std::vector<std::string> sets;
  std::string ccx = "ccx";
  bool no_plots = false;
};

json stats(const std::vector<double>& v) {
  std::vector<double> x;
  for (double d : v)
    if (std::isfinite(d)) x.push_back(d);
  if (x.empty()) return json{{"count", 0}};
  const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
  const double mean = std::accumulate(x.begin(), x.end(), 0.0) / static_cast<double>(x.size());
  return json{{"mean", mean}, {"min", *lo}, {"max", *hi}, {"count", x.size()}};
}

void write_outputs(const fs::path& dir, const fe::PlanetaryFeDef& def, const std::vector<std::optional<fe::PlanetaryFePosition>>& done,
                   double rbs, json& summary, bool plots) {
  const int n = def.spec.planets;
  const double mesh_period = 2.0 * M_PI / def.spec.sun.teeth;
  OutputFile te(dir / "te_loaded.csv", Durability::Record);
  te << std::setprecision(12);
  te << "position,sun_turn_rad,mesh_phase,te_geometric_rad,te_elastic_rad,te_loaded_rad,te_loaded_urad,"
        "te_loaded_base_um,te_fe_low_rad,te_fe_full_rad,sun_mesh_torque_low_N_m,sun_mesh_torque_N_m,ccx_wall_s\n";
  OutputFile ms(dir / "mesh_stiffness.csv", Durability::Record);
  ms << std::setprecision(12);
  ms << "position,sun_turn_rad,mesh_phase";
  for (int k = 0; k < n; ++k) {
    const std::string p = "planet_" + std::to_string(k);
    ms << ",sun_" << p << "_force_N," << p << "_ring_force_N,sun_" << p << "_stiffness_N_per_m," << p << "_ring_stiffness_N_per_m," << p
       << "_load_share";
  }
  ms << '\n';
  // The tracked tooth (the faulty one, else planet 0's tooth 0): its sun-side force and root stresses.
  OutputFile tf(dir / "tooth_forces.csv", Durability::Record);
  tf << std::setprecision(12);
  tf << "position,sun_turn_rad,mesh_phase,planet,tooth,force_N\n";
  OutputFile rs(dir / "root_stress.csv", Durability::Record);
  rs << std::setprecision(12);
  rs << "position,sun_turn_rad,mesh_phase,planet,tooth,side,tooth_force_N,sigma1_max_Pa,sigma2_min_Pa,"
        "von_mises_max_Pa,sigma1_max_low_load_Pa,elements\n";
  // Largest root σ1 (either side), MPa, of teeth t−1, t, t+1 of the tracked planet, per position.
  std::map<int, std::vector<double>> root_by_tooth;
  std::vector<double> tracked_force;
  json root_peaks;  // tooth → the largest σ1 over the sweep, where
  constexpr double kLoadedPairShare = 0.02;
  std::vector<int> n_sp;  // loaded tooth pairs per sun–planet sample (parallel to k_sp)
  std::vector<double> mesh_torque_fraction;  // torque through the teeth / applied torque
  std::vector<double> te_loaded, te_elastic, k_sp, k_pr, share_max, phase_col, te_col, tel_col, kcol;
  double first_turn = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t i = 0; i < done.size(); ++i) {
    if (!done[i]) continue;
    const fe::PlanetaryFePosition& p = *done[i];
    if (std::isnan(first_turn)) first_turn = p.sun_turn_rad;
    const double phase = (p.sun_turn_rad - first_turn) / mesh_period;
    te << i << ',' << p.sun_turn_rad << ',' << phase << ',' << p.te_geometric_rad << ',' << p.te_elastic_rad << ',' << p.te_loaded_rad
       << ',' << p.te_loaded_rad * 1e6 << ',' << p.te_loaded_rad * rbs * 1e6 << ',' << p.te_fe_low_rad << ',' << p.te_fe_full_rad << ','
       << p.sun_mesh_torque_low_N_m << ',' << p.sun_mesh_torque_N_m << ',' << p.wall_time_s << '\n';
    mesh_torque_fraction.push_back(p.sun_mesh_torque_N_m / def.sun_torque_N_m);
    te_loaded.push_back(p.te_loaded_rad);
    te_elastic.push_back(p.te_elastic_rad);
    phase_col.push_back(phase);
    te_col.push_back(p.te_loaded_rad * 1e6);
    tel_col.push_back(p.te_elastic_rad * 1e6);
    const double total = std::accumulate(p.sun_planet_force_N.begin(), p.sun_planet_force_N.end(), 0.0);
    ms << i << ',' << p.sun_turn_rad << ',' << phase;
    double smax = 0;
    for (int k = 0; k < n; ++k) {
      const double share = total > 0 ? p.sun_planet_force_N[k] * n / total : 0.0;
      smax = std::max(smax, share);
      ms << ',' << p.sun_planet_force_N[k] << ',' << p.planet_ring_force_N[k] << ',' << p.sun_planet_stiffness_N_per_m[k] << ','
         << p.planet_ring_stiffness_N_per_m[k] << ',' << share;
      k_sp.push_back(p.sun_planet_stiffness_N_per_m[k]);
      // Loaded tooth pairs of this sun–planet mesh: teeth carrying more than kLoadedPairShare of
      // the planet's sun-mesh force.
      int pairs = 0;
      for (const auto& tf_k : p.sun_mesh_tooth_force_N[static_cast<size_t>(k)])
        if (tf_k.second > kLoadedPairShare * p.sun_planet_force_N[k]) ++pairs;
      n_sp.push_back(pairs);
      k_pr.push_back(p.planet_ring_stiffness_N_per_m[k]);
    }
    kcol.push_back(p.sun_planet_stiffness_N_per_m[0]);
    std::map<int, double> tracked_planet_force;  // tooth → sun force on it, tracked planet
    for (int k = 0; k < n; ++k)
      for (const auto& [tooth, f] : p.sun_mesh_tooth_force_N[static_cast<size_t>(k)]) {
        tf << i << ',' << p.sun_turn_rad << ',' << phase << ',' << k << ',' << tooth << ',' << f << '\n';
        if (k == p.tracked.planet) tracked_planet_force[tooth] = f;
      }
    tracked_force.push_back(tracked_planet_force[p.tracked.tooth]);
    std::map<int, double> sigma1_of_tooth;
    for (const fe::RootStress& r : p.tracked_root_stress) {
      const bool ccw = r.side == Flank::Ccw;
      const double f = tracked_planet_force[r.tooth];
      rs << i << ',' << p.sun_turn_rad << ',' << phase << ',' << p.tracked.planet << ',' << r.tooth << ',' << (ccw ? "ccw" : "cw") << ','
         << f << ',' << r.sigma1_max_Pa << ',' << r.sigma2_min_Pa << ',' << r.von_mises_max_Pa << ',' << r.sigma1_max_low_Pa << ','
         << r.elements << '\n';
      sigma1_of_tooth[r.tooth] = sigma1_of_tooth.contains(r.tooth) ? std::max(sigma1_of_tooth[r.tooth], r.sigma1_max_Pa) : r.sigma1_max_Pa;
      json& peak = root_peaks[std::to_string(r.tooth)];
      if (!peak.contains("sigma1_max_Pa") || r.sigma1_max_Pa > peak["sigma1_max_Pa"].get<double>())
        peak = {{"sigma1_max_Pa", r.sigma1_max_Pa},
                {"side", ccw ? "ccw" : "cw"},
                {"position", i},
                {"mesh_phase", phase},
                {"tooth_force_N", f},
                {"von_mises_max_Pa", r.von_mises_max_Pa}};
    }
    for (const auto& [tooth, s1] : sigma1_of_tooth) root_by_tooth[tooth].push_back(s1 * 1e-6);
    share_max.push_back(smax);
    ms << '\n';
  }
  for (OutputFile* f : {&te, &ms, &tf, &rs}) f->commit();
  auto range = [&](const std::vector<double>& v) {
    if (v.empty()) return json{{"count", 0}};
    const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
    return json{{"min_rad", *lo},
                {"max_rad", *hi},
                {"p2p_rad", *hi - *lo},
                {"p2p_urad", (*hi - *lo) * 1e6},
                {"p2p_base_um", (*hi - *lo) * rbs * 1e6}};
  };
  summary["positions_solved"] = te_loaded.size();
  summary["te_loaded"] = range(te_loaded);
  summary["te_elastic"] = range(te_elastic);
  summary["mesh_stiffness_N_per_m"] = stats(k_sp);  // sun–planet meshes, all planets and positions
  summary["planet_ring_stiffness_N_per_m"] = stats(k_pr);
  const double face = def.spec.sun.face_width_m;
  if (json k = stats(k_sp); k.contains("mean"))
    summary["mesh_stiffness_N_per_mm_per_um"] = {{"mean", k["mean"].get<double>() / face * 1e-9},
                                                 {"min", k["min"].get<double>() / face * 1e-9},
                                                 {"max", k["max"].get<double>() / face * 1e-9}};
  summary["load_sharing_max_over_mean"] = stats(share_max);
  summary["sun_mesh_torque_over_applied"] = stats(mesh_torque_fraction);
  if (!tracked_force.empty()) {
    const fe::TrackedTooth t = fe::tracked_tooth(def);
    summary["tracked_tooth"] = {{"planet", t.planet},
                                {"tooth", t.tooth},
                                {"faulty", t.faulty},
                                {"sun_force_N", stats(tracked_force)},
                                {"root_stress_peak_by_tooth", root_peaks}};
  }

  // Stiffness tables for the dynamics (contact.stiffness_tables). The FE mesh compliance is the
  // teeth (n pairs in parallel) in series with the gear bodies, 1/k = 1/(n k_pair) + 1/k_body.
  // n is the FE's own count of loaded pairs where the deck splits the mesh per tooth
  // (sun–planet); elsewhere (planet–ring) the samples split into the softer and the stiffer half
  // of their range, n = 1 and 2 (contact ratio between 1 and 2). The table holds the tooth part
  // per pair and the scenario entry the bodies (body_stiffness_N_per_m: Bullet's bodies are
  // rigid). Without two pair counts, or when k_min and k_max are within kMinSeriesSpread, the
  // table holds mean k / (ε b) instead. Fit on a healthy sweep: open pairs (k = 0) are skipped.
  constexpr double kMinSeriesSpread = 1.05;
  // body_a, body_b: the planetary macro's body names (sun, planet, ring) for the scenario entry.
  auto table = [&](const char* file, const char* body_a, const char* body_b, const GearSpec& a, const GearSpec& b,
                   const std::vector<double>& ks, std::vector<int> ns, const char* count_source) {
    std::vector<double> k;
    std::vector<int> pairs_of;
    if (ns.empty()) {  // split by range
      std::vector<double> ok;
      for (double v : ks)
        if (std::isfinite(v) && v > 0) ok.push_back(v);
      if (ok.empty()) return;
      const auto [lo, hi] = std::minmax_element(ok.begin(), ok.end());
      for (double v : ks) ns.push_back(v > 0.5 * (*lo + *hi) ? 2 : 1);
    }
    for (std::size_t i = 0; i < ks.size(); ++i)
      if (std::isfinite(ks[i]) && ks[i] > 0 && ns[i] > 0) {
        k.push_back(ks[i]);
        pairs_of.push_back(ns[i]);
      }
    if (k.empty()) return;
    const auto [lo, hi] = std::minmax_element(k.begin(), k.end());
    const double mean = std::accumulate(k.begin(), k.end(), 0.0) / static_cast<double>(k.size());
    const MeshGeometry g = analyse_mesh(a, b, zero_backlash_centre_distance(a, b));
    json info = {{"gear_a", a.name},
                 {"gear_b", b.name},
                 {"k_min_N_per_m", *lo},
                 {"k_max_N_per_m", *hi},
                 {"samples", k.size()},
                 {"effective_contact_ratio", g.effective_contact_ratio},
                 {"mean_over_contact_ratio_N_per_m_per_m", mean / (g.effective_contact_ratio * face)}};
    // Least squares y = s x + c with x = 1/n, y = 1/k.
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    std::map<int, int> per_n;
    for (std::size_t i = 0; i < k.size(); ++i) {
      const double x = 1.0 / pairs_of[i], y = 1.0 / k[i];
      sx += x, sy += y, sxx += x * x, sxy += x * y;
      ++per_n[pairs_of[i]];
    }
    const double m = static_cast<double>(k.size()), det = m * sxx - sx * sx;
    const double slope = det > 0 ? (m * sxy - sx * sy) / det : 0.0, icpt = det > 0 ? (sy - slope * sx) / m : 0.0;
    json counts;
    for (const auto& [pairs, c] : per_n) counts[std::to_string(pairs)] = c;
    info["pair_counts"] = counts;
    info["pair_count_source"] = count_source;
    // The least-squares fit over all samples, for reference.
    if (per_n.size() >= 2 && slope > 0 && icpt > 0) {
      double rms = 0;
      for (std::size_t i = 0; i < k.size(); ++i) {
        const double fit = 1.0 / (slope / pairs_of[i] + icpt);  // 1/(1/(n k_pair) + 1/k_body)
        rms += std::pow(k[i] / fit - 1.0, 2) / m;
      }
      info["least_squares"] = {{"k_pair_N_per_m", 1.0 / slope}, {"k_body_N_per_m", 1.0 / icpt}, {"fit_rms_relative", std::sqrt(rms)}};
    }
    // The table: the series model through the softest sample (one pair) and the stiffest (two
    // pairs), 1/k_min − 1/k_max = 1/(2 k_pair). The loaded TE's ripple is set by these two
    // states; the samples between are partly engaged second pairs (chord gaps of the FE boundary,
    // docs/fe-results.md) that pull a least-squares fit towards stiffer teeth and a smaller ripple.
    double c;
    if (per_n.size() >= 2 && *hi > kMinSeriesSpread * *lo) {
      const double k_pair = 1.0 / (2.0 * (1.0 / *lo - 1.0 / *hi));
      const double k_body = 1.0 / (1.0 / *lo - 1.0 / k_pair);
      c = k_pair / face;
      info["method"] = "series fit 1/k = 1/(n k_pair) + 1/k_body through k_min (n = 1) and k_max (n = 2)";
      info["k_pair_N_per_m"] = k_pair;
      info["k_body_N_per_m"] = k_body;
      // The entry for contact.stiffness_tables: the tooth part per pair, the bodies in series.
      char entry[256];
      std::snprintf(entry, sizeof entry, "{gears: [%s, %s], file: %s, body_stiffness_N_per_m: %.6g}", body_a, body_b, file, k_body);
      info["scenario_entry"] = entry;
    } else {
      c = mean / (g.effective_contact_ratio * face);
      info["method"] = "mean / (effective contact ratio × face width): one pair count, or k_min and k_max within 5 %";
    }
    info["stiffness_N_per_m_per_m"] = c;
    const GearDimensions d = gear_dimensions(a);
    OutputFile t(dir / file);
    t << std::setprecision(12) << "radius_a_m,stiffness_N_per_m_per_m\n"
      << d.root_radius_m << ',' << c << '\n'
      << d.tip_radius_m << ',' << c << '\n';
    t.commit();
    summary["stiffness_tables"][file] = info;
  };
  table("fe_stiffness_sun_planet.csv", "sun", "planet", def.spec.sun, def.spec.planet, k_sp, n_sp,
        "FE: teeth carrying > 2 % of the mesh force");
  table("fe_stiffness_planet_ring.csv", "planet", "ring", def.spec.planet, def.spec.ring, k_pr, {},
        "softer/stiffer half of the sampled range");
  if (plots && te_loaded.size() >= 2) {
    write_output_file(dir / "te_loaded.svg",
                      gnuplot_svg(data_block("d", {phase_col, te_col, tel_col}) +
                                  "set xlabel 'sun turn relative to the carrier, mesh periods'; set ylabel 'TE, µrad'; set grid\n"
                                  "set y2label 'elastic part, µrad'; set y2tics; set ytics nomirror\n"
                                  "plot $d using 1:2 with linespoints title 'loaded TE (θ_s − i θ_c)', "
                                  "$d using 1:3 axes x1y2 with linespoints title 'elastic part'\n"));
    if (root_by_tooth.size() == 3) {
      const fe::TrackedTooth t = fe::tracked_tooth(def);
      const int z = def.planet_gears.empty() ? def.spec.planet.teeth : def.planet_gears[0].teeth;
      const int before = (t.tooth + z - 1) % z, after = (t.tooth + 1) % z;
      write_output_file(
          dir / "root_stress.svg",
          gnuplot_svg(data_block("d", {phase_col, root_by_tooth[before], root_by_tooth[t.tooth], root_by_tooth[after], tracked_force}) +
                      "set xlabel 'sun turn relative to the carrier, mesh periods'; set ylabel 'largest root σ1, MPa'; set grid\n"
                      "set y2label 'sun force on the tracked tooth, N'; set y2tics; set ytics nomirror\n"
                      "plot $d using 1:2 with linespoints title 'tooth " +
                      std::to_string(before) + "', $d using 1:3 with linespoints title 'tooth " + std::to_string(t.tooth) +
                      (t.faulty ? " (faulty)" : "") + "', $d using 1:4 with linespoints title 'tooth " + std::to_string(after) +
                      "', $d using 1:5 axes x1y2 with linespoints title 'force on tooth " + std::to_string(t.tooth) + "'\n"));
    }
    write_output_file(dir / "mesh_stiffness.svg",
                      gnuplot_svg(data_block("d", {phase_col, kcol}) +
                                  "set xlabel 'sun turn relative to the carrier, mesh periods'; set ylabel 'N/m'; set grid\n"
                                  "plot $d using 1:2 with linespoints title 'sun–planet 0 secant mesh stiffness'\n"));
  }
}

void fe_te(const FeTeOptions& o) {
  const physics::Scenario s = input::load_scenario(o.scenario, o.sets);
  if (!s.fe)
    throw InputError(o.scenario +
                     ": no fe: section (fe-te needs its settings; see the fe: section of assets/scenarios/paper_te_loaded.yaml)");
  if (!s.planetary)
    throw InputError(o.scenario + ": fe-te solves planetary trains of generated gears (the planetary: macro with a spec's gear names)");
  if (fe::find_executable(o.ccx).empty())
    throw InputError("CalculiX solver '" + o.ccx + "' not found on PATH (Debian package calculix-ccx; or give --ccx PATH)");
  const physics::FeTeDef& f = *s.fe;
  const fs::path dir(o.out_dir);
  // The outputs in the manifest; ccx/ is CalculiX's work folder (a deck, log and results per
  // position, written by ccx itself), kept for inspection and not listed.
  OutputFolder folder(dir, "gearsim fe-te");
  folder.declare({"te_loaded.csv", "mesh_stiffness.csv", "tooth_forces.csv", "root_stress.csv", "te_loaded.svg", "root_stress.svg",
                  "mesh_stiffness.svg", "fe_stiffness_sun_planet.csv", "fe_stiffness_planet_ring.csv", "summary.json"});
  std::error_code ec;
  fs::create_directories(dir / "ccx", ec);
  if (ec) throw InputError(dir.string() + ": cannot create the output folder: " + ec.message());

  fe::PlanetaryFeDef def;
  def.spec = s.planetary->spec;
  def.planet_gears = s.planetary->planet_gears;
  auto thin = [&](GearSpec& g) { g.thinning_per_flank_m += f.thinning_per_flank_m; };
  thin(def.spec.sun);
  thin(def.spec.planet);
  thin(def.spec.ring);
  for (GearSpec& g : def.planet_gears) thin(g);
  def.sizing.flank_size_m = f.flank_size_m;
  def.sizing.core_size_m = f.core_size_m;
  def.sizing.transition_m = f.transition_m;
  def.sizing.max_sagitta_m = f.max_sagitta_m;
  def.sun_torque_N_m = f.sun_torque_N_m;
  def.friction = f.friction;
  def.element_type = f.element_type;
  def.ccx = o.ccx;

  const auto wall0 = std::chrono::steady_clock::now();
  auto since = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count(); };
  std::cerr << s.name << ": meshing (flank " << f.flank_size_m * 1e3 << " mm, sagitta ≤ " << f.max_sagitta_m * 1e6 << " µm)..."
            << std::flush;
  const fe::PlanetaryFeMeshes meshes = fe::mesh_planetary(def);
  const double mesh_wall = since();
  std::cerr << " sun " << meshes.sun.quality.quads << ", planet " << meshes.planets[0].quality.quads << ", ring "
            << meshes.ring.quality.quads << " quads (" << std::fixed << std::setprecision(1) << mesh_wall << " s)\n";
  const std::vector<double> turns = fe::sweep_turns(def, f.positions_per_mesh, f.mesh_periods);
  const double rbs = gear_dimensions(def.spec.sun).base_radius_m;

  json summary;
  summary["scenario"] = s.name;
  summary["scenario_file"] = fs::absolute(o.scenario).lexically_normal().string();
  summary["overrides"] = o.sets;
  summary["fe"] = {{"flank_size_m", f.flank_size_m},
                   {"core_size_m", f.core_size_m},
                   {"transition_m", f.transition_m},
                   {"max_sagitta_m", f.max_sagitta_m},
                   {"thinning_per_flank_m", f.thinning_per_flank_m},
                   {"sun_torque_N_m", f.sun_torque_N_m},
                   {"torque_source", f.torque_source},
                   {"friction", f.friction},
                   {"element_type", f.element_type},
                   {"positions_per_mesh", f.positions_per_mesh},
                   {"mesh_periods", f.mesh_periods},
                   {"jobs", f.jobs},
                   {"low_load_fraction", fe::kLowLoadFraction}};
  summary["quads"] = {{"sun", meshes.sun.quality.quads}, {"planet", meshes.planets[0].quality.quads}, {"ring", meshes.ring.quality.quads}};
  summary["min_scaled_jacobian"] = std::min(
      {meshes.sun.quality.min_scaled_jacobian, meshes.planets[0].quality.min_scaled_jacobian, meshes.ring.quality.min_scaled_jacobian});
  summary["sun_base_radius_m"] = rbs;
  summary["positions"] = turns.size();

  std::vector<std::optional<fe::PlanetaryFePosition>> done(turns.size());
  std::size_t finished = 0;
  double ccx_total = 0;
  std::string status = "completed", error;
  try {
    fe::solve_positions(def, meshes, turns, dir / "ccx", f.jobs, [&](std::size_t i, const fe::PlanetaryFePosition& p) {
      done[i] = p;
      ++finished;
      ccx_total += p.wall_time_s;
      std::cerr << "  position " << finished << "/" << turns.size() << " (pos_" << std::setw(3) << std::setfill('0') << i
                << std::setfill(' ') << "): TE " << std::setprecision(2) << p.te_loaded_rad * 1e6 << " µrad, elastic "
                << p.te_elastic_rad * 1e6 << " µrad, sun–planet " << std::setprecision(1) << p.sun_planet_force_N[0] << " N; ccx "
                << p.wall_time_s << " s, elapsed " << since() << " s\n";
    });
  } catch (const std::exception& e) {
    status = "failed";
    error = e.what();
  }
  summary["status"] = status;
  if (!error.empty()) summary["error"] = error;
  summary["wall_seconds"] = since();
  summary["mesh_wall_seconds"] = mesh_wall;
  summary["ccx_seconds_total"] = ccx_total;
  write_outputs(dir, def, done, rbs, summary, !o.no_plots && status == "completed");
  write_output_file(dir / "summary.json", summary.dump(2) + "\n", Durability::Record);
  if (status != "completed")
    throw RunStopped(kExitToolFailed, "fe-te stopped after " + std::to_string(finished) + " of " + std::to_string(turns.size()) +
                                          " positions (kept in " + dir.string() + "/te_loaded.csv): " + error);
  const json& t = summary["te_loaded"];
  std::cout << s.name << ": loaded TE " << std::setprecision(3) << t["min_rad"].get<double>() * 1e6 << " … "
            << t["max_rad"].get<double>() * 1e6 << " µrad, peak-to-peak " << t["p2p_urad"].get<double>() << " µrad ("
            << t["p2p_base_um"].get<double>() << " µm on the sun base circle); mean sun–planet mesh stiffness "
            << summary["mesh_stiffness_N_per_m"]["mean"].get<double>() << " N/m; " << std::setprecision(0)
            << summary["wall_seconds"].get<double>() << " s wall → " << dir.string() << "\n";
}

}  // namespace

void register_fe_te(CLI::App& app) {
  auto o = std::make_shared<FeTeOptions>();
  CLI::App* sub = app.add_subcommand(
      "fe-te", "Loaded transmission error by finite elements (Gmsh + CalculiX): te_loaded.csv, mesh_stiffness.csv, summary.json in --out.");
  sub->add_option("scenario", o->scenario, "Scenario file with a planetary: train and an fe: section.")
      ->required()
      ->check(CLI::ExistingFile);
  sub->add_option("--out", o->out_dir, "Output folder (created if missing).")->required();
  sub->add_option("--set", o->sets, "Override a scenario value: key.path=value (repeatable), e.g. fe.positions_per_mesh=4.");
  sub->add_option("--ccx", o->ccx, "CalculiX executable (name on PATH or a path).");
  sub->add_flag("--no-plots", o->no_plots, "Do not draw the SVG plots (gnuplot).");
  sub->callback([o] { fe_te(*o); });
}

}  // namespace gearsim::app
