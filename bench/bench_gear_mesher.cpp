// Benchmark: quad meshes (gmsh) of the paper's gears at the flank sizes 0.4 mm (paper) and
// 0.2 mm: node and quad counts, shape (angles, min scaled Jacobian) and median meshing wall time.
// Usage: bench_gear_mesher [repeats=3] [toothed-loop sagitta limit, m]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <vector>

#include "geometry/gear_profile.hpp"
#include "fe/gear_mesher.hpp"

using namespace gearsim;
using Clock = std::chrono::steady_clock;

namespace {

// The paper's gears (assets/specs/paper_gearset.yaml): bores 8 / 10 mm, ring rim 110 mm.
GearSpec gear(const char* name, int teeth, bool internal, double bore_or_rim_m) {
  GearSpec s;
  s.name = name;
  s.teeth = teeth;
  s.module_m = 1e-3;
  s.face_width_m = 10e-3;
  if (internal) {
    s.kind = GearKind::Internal;
    s.rim_diameter_m = bore_or_rim_m;
  } else {
    s.bore_diameter_m = bore_or_rim_m;
  }
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 3;
  const double deg = 180.0 / std::numbers::pi;
  std::printf("%-7s %8s %7s %7s %9s %9s %7s %10s\n", "gear", "flank_mm", "nodes", "quads", "min_deg", "max_deg", "min_SJ", "median_ms");
  const double sagitta = argc > 2 ? std::atof(argv[2]) : fe::MeshSizingDef{}.max_sagitta_m;
  std::printf("toothed-loop sagitta limit %.2f um\n", sagitta * 1e6);
  for (double flank : {0.4e-3, 0.2e-3}) {
    for (const GearSpec& s : {gear("sun", 24, false, 8e-3), gear("planet", 36, false, 10e-3), gear("ring", 96, true, 110e-3)}) {
      const GearOutline outline = make_gear_outline(s);
      fe::MeshSizingDef sizing;
      sizing.flank_size_m = flank;
      sizing.max_sagitta_m = sagitta;
      std::vector<double> ms;
      fe::GearMesh m;
      for (int i = 0; i < repeats; ++i) {
        const auto t0 = Clock::now();
        m = fe::mesh_gear_outline(outline, s.kind, sizing);
        ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
      }
      std::sort(ms.begin(), ms.end());
      const auto& q = m.quality;
      std::printf("%-7s %8.1f %7d %7d %9.1f %9.1f %7.3f %10.0f%s\n", s.name.c_str(), flank * 1e3, q.nodes, q.quads, q.min_angle_rad * deg,
                  q.max_angle_rad * deg, q.min_scaled_jacobian, ms[ms.size() / 2], m.subdivided ? "  (subdivided)" : "");
    }
  }
}
