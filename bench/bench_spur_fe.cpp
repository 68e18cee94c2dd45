// Study: FE mesh stiffness of one external spur pair against ISO 6336-1 (method B) and the
// potential-energy model, at several flank element sizes: per roll position the secant stiffness
// (bodies included, and with both bodies' torsion taken out), the PE value at the same contact
// points, the load per tooth pair and the mesh-boundary gaps; the mean over one base pitch, the
// single-pair value at the pitch point, and ccx wall times. Two ccx processes at a time.
// Usage: bench_spur_fe [z1=20] [z2=31] [positions=8] [flank sizes in mm, default 0.8 0.4 0.2]
//        [CPS4 | CPS4R (default)]
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "fe/spur_pair_fe.hpp"

using namespace gearsim;
using namespace gearsim::fe;
using Clock = std::chrono::steady_clock;

namespace {

constexpr int kWorkers = 2;  // ccx processes at once (2 shared cores)
constexpr double kPerWidth = 1e-9;  // N/m² → N/(mm·µm)

}  // namespace

int main(int argc, char** argv) {
  SpurPairFeDef def;
  if (argc > 1) def.pair.pinion_teeth = std::atoi(argv[1]);
  if (argc > 2) def.pair.wheel_teeth = std::atoi(argv[2]);
  const int n = argc > 3 ? std::max(1, std::atoi(argv[3])) : 8;
  std::vector<double> sizes_mm;
  for (int i = 4; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "CPS4" || a == "CPS4R")
      def.element_type = a;
    else
      sizes_mm.push_back(std::atof(argv[i]));
  }
  if (sizes_mm.empty()) sizes_mm = {0.8, 0.4, 0.2};

  const SpurPairPath path = spur_pair_path(def.pair);
  const SpurPairReferences ref = spur_pair_references(def.pair);
  const double b = def.pair.face_width_m, rb1 = path.pinion_base_radius_m;
  std::printf(
      "pair z%d/%d m %.2f mm b %.1f mm thinning %.0f um/flank, bores %.2f of root, T %.2f/%.2f N m, "
      "friction %.3f, %s\n",
      def.pair.pinion_teeth, def.pair.wheel_teeth, def.pair.module_m * 1e3, b * 1e3, def.pair.thinning_per_flank_m * 1e6,
      def.pair.bore_over_root, def.low_load_fraction * def.pinion_torque_N_m, def.pinion_torque_N_m, def.friction,
      def.element_type.c_str());
  std::printf("path: start %.4f end %.4f pitch %.4f mm, p_b %.4f mm, eps_alpha %.4f, T/r_b1 = %.1f N\n", path.start_roll_m * 1e3,
              path.end_roll_m * 1e3, path.pitch_roll_m * 1e3, path.base_pitch_m * 1e3, path.contact_ratio, def.pinion_torque_N_m / rb1);
  std::printf("ISO c' %.2f  c'_th %.2f  c_ga %.2f  c_ga,th %.2f  PE mean %.2f  PE pitch point %.2f  [N/(mm um)]\n",
              ref.iso_single_N_per_m2 * kPerWidth, ref.iso_single_theory_N_per_m2 * kPerWidth, ref.iso_mesh_N_per_m2 * kPerWidth,
              ref.iso_mesh_theory_N_per_m2 * kPerWidth, ref.pe_mean_N_per_m2 * kPerWidth, ref.pe_pitch_point_N_per_m2 * kPerWidth);

  // The n positions over one base pitch, then the pitch point.
  std::vector<double> rolls = rolls_over_base_pitch(path, n);
  rolls.push_back(path.pitch_roll_m);
  const std::filesystem::path root = std::filesystem::temp_directory_path() / "gearsim_bench_spur_fe";

  for (double size_mm : sizes_mm) {
    def.sizing.flank_size_m = size_mm * 1e-3;
    const auto t0 = Clock::now();
    const SpurPairMeshes meshes = mesh_spur_pair(def);
    const double mesh_s = std::chrono::duration<double>(Clock::now() - t0).count();
    const std::filesystem::path dir = root / ("flank_" + std::to_string(size_mm) + "_" + def.element_type);
    // Body torsion of both gears, then the positions, kWorkers solves at a time.
    std::vector<SpurPairFePosition> pos(rolls.size());
    std::vector<std::string> failed(rolls.size());  // ccx's message for a position that failed
    GearBodyTorsion tp, tw;
    std::vector<std::string> errors;
    std::mutex mu;
    std::atomic<int> next{-2};
    auto worker = [&] {
      for (int i = next++; i < static_cast<int>(rolls.size()); i = next++) {
        try {
          if (i == -2)
            tp = solve_gear_body_torsion(def, meshes, true, dir / "torsion_pinion");
          else if (i == -1)
            tw = solve_gear_body_torsion(def, meshes, false, dir / "torsion_wheel");
          else
            pos[static_cast<size_t>(i)] =
                solve_spur_pair_position(def, meshes, rolls[static_cast<size_t>(i)], dir / ("pos" + std::to_string(i)));
        } catch (const std::runtime_error& e) {
          std::lock_guard<std::mutex> lock(mu);
          if (i >= 0)
            failed[static_cast<size_t>(i)] = e.what();  // a solver failure: reported in its row
          else
            errors.push_back("torsion job " + std::to_string(i) + ": " + e.what());
        } catch (const std::exception& e) {
          std::lock_guard<std::mutex> lock(mu);
          errors.push_back("job " + std::to_string(i) + ": " + e.what());
        }
      }
    };
    std::vector<std::thread> threads;
    for (int w = 0; w < kWorkers; ++w) threads.emplace_back(worker);
    for (auto& t : threads) t.join();
    const double study_s = std::chrono::duration<double>(Clock::now() - t0).count();
    for (const auto& e : errors) std::printf("ERROR %s\n", e.c_str());
    if (!errors.empty()) return 1;

    std::printf("\nflank %.2f mm: pinion %d quads, wheel %d quads (min SJ %.2f / %.2f), meshing %.1f s\n", size_mm,
                meshes.pinion.quality.quads, meshes.wheel.quality.quads, meshes.pinion.quality.min_scaled_jacobian,
                meshes.wheel.quality.min_scaled_jacobian, mesh_s);
    std::printf(
        "body torsion [rad/(N m)]: pinion FE %.4e (annulus %.4e), wheel FE %.4e (annulus %.4e); "
        "along the line of action %.3e + %.3e m/N\n",
        tp.rotation_per_torque_rad_per_N_m, tp.annulus_closed_form_rad_per_N_m, tw.rotation_per_torque_rad_per_N_m,
        tw.annulus_closed_form_rad_per_N_m, tp.line_of_action_compliance_m_per_N, tw.line_of_action_compliance_m_per_N);
    std::printf("%8s %5s %6s %11s %11s %8s %8s %7s %7s %7s %6s %6s  %-26s %-22s %6s\n", "roll_mm", "PEprs", "loaded", "th_low_rad",
                "th_full_rad", "F_low_N", "F_full_N", "F/Frb", "k_FE", "k_noTor", "k_PE", "FE/PE", "pair forces N (roll mm)", "FE gaps um",
                "ccx_s");
    double sum = 0, sum_nt = 0, sum_pe = 0;
    int solved = 0;
    for (size_t i = 0; i < pos.size(); ++i) {
      const SpurPairFePosition& p = pos[i];
      if (!failed[i].empty()) {
        std::printf("%8.4f  ccx failed: %s\n", rolls[i] * 1e3, failed[i].substr(failed[i].rfind("*ERROR")).c_str());
        continue;
      }
      const double k = p.stiffness_N_per_m, knt = stiffness_without_body_torsion(k, tp, tw);
      if (i < static_cast<size_t>(n)) {
        ++solved;
        sum += k;
        sum_nt += knt;
        sum_pe += p.pe_stiffness_N_per_m;
      }
      std::string forces, gaps;
      char buf[64];
      for (const auto& q : p.pairs) {
        std::snprintf(buf, sizeof buf, "%.0f(%.2f) ", q.force_full_N, q.roll_m * 1e3);
        forces += buf;
        if (q.on_path) {
          std::snprintf(buf, sizeof buf, "%.1f ", q.fe_gap_m * 1e6);
          gaps += buf;
        }
      }
      std::printf("%8.4f %5d %6d %11.4e %11.4e %8.1f %8.1f %7.4f %7.2f %7.2f %6.2f %6.3f  %-26s %-22s %6.1f%s\n", p.roll_m * 1e3,
                  p.pe_pairs, p.loaded_pairs, p.pinion_rotation_low_rad, p.pinion_rotation_full_rad, p.contact_force_low_N,
                  p.contact_force_full_N, p.contact_force_full_N / (p.torque_full_N_m / rb1), k / b * kPerWidth, knt / b * kPerWidth,
                  p.pe_stiffness_N_per_m / b * kPerWidth, k / p.pe_stiffness_N_per_m, forces.c_str(), gaps.c_str(), p.wall_time_s,
                  i == pos.size() - 1 ? "  (pitch point)" : "");
    }
    std::printf(
        "mean over %d of %d positions [N/(mm um)]: FE %.2f, FE without body torsion %.2f, PE at the same "
        "positions %.2f (PE mean %.2f); ISO c_ga %.2f, c_ga,th %.2f\n",
        solved, n, sum / solved / b * kPerWidth, sum_nt / solved / b * kPerWidth, sum_pe / solved / b * kPerWidth,
        ref.pe_mean_N_per_m2 * kPerWidth, ref.iso_mesh_N_per_m2 * kPerWidth, ref.iso_mesh_theory_N_per_m2 * kPerWidth);
    if (failed.back().empty()) {
      const double kp = pos.back().stiffness_N_per_m, kpnt = stiffness_without_body_torsion(kp, tp, tw);
      std::printf(
          "pitch point (single pair) [N/(mm um)]: FE %.2f, without body torsion %.2f, PE %.2f; ISO c' %.2f, "
          "c'_th %.2f\n",
          kp / b * kPerWidth, kpnt / b * kPerWidth, ref.pe_pitch_point_N_per_m2 * kPerWidth, ref.iso_single_N_per_m2 * kPerWidth,
          ref.iso_single_theory_N_per_m2 * kPerWidth);
    }
    std::printf("wall: study %.0f s (2 workers), ccx per position median %.1f s\n", study_s, [&] {
      std::vector<double> w;
      for (size_t i = 0; i < pos.size(); ++i)
        if (failed[i].empty()) w.push_back(pos[i].wall_time_s);
      if (w.empty()) return 0.0;
      std::sort(w.begin(), w.end());
      return w[w.size() / 2];
    }());
    std::fflush(stdout);
  }
  return 0;
}
