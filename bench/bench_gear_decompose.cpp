// Benchmark: generate and decompose each of the paper's gears (outline → prism mesh → exact
// convex pieces), median wall time over repeated runs, piece counts. Target (issue 2): the
// 96-tooth ring well under 1 s. Usage: bench_gear_decompose [repeats=20]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "geometry/convex_decomposition.hpp"
#include "geometry/extrude.hpp"
#include "geometry/gear_body.hpp"
#include "geometry/gear_profile.hpp"

using namespace gearsim;
using Clock = std::chrono::steady_clock;

namespace {

GearSpec gear(const char* name, int teeth, bool internal) {
  GearSpec s;
  s.name = name;
  s.teeth = teeth;
  s.module_m = 1e-3;
  s.face_width_m = 10e-3;
  if (internal) {
    s.kind = GearKind::Internal;
    s.rim_diameter_m = 110e-3;
  } else {
    s.bore_diameter_m = 8e-3;
  }
  return s;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  const int repeats = argc > 1 ? std::atoi(argv[1]) : 20;
  std::printf("%-8s %8s %10s %10s %10s %10s %8s\n", "gear", "outline", "outline_ms", "extrude_ms", "decomp_ms", "total_ms", "pieces");
  for (const GearSpec& s : {gear("sun", 24, false), gear("planet", 36, false), gear("ring", 96, true)}) {
    std::vector<double> t_outline, t_extrude, t_decomp, t_total;
    std::size_t pieces = 0, outline_points = 0;
    for (int i = 0; i < repeats; ++i) {
      const auto t0 = Clock::now();
      const GearOutline o = make_gear_outline(s);
      const auto t1 = Clock::now();
      const TriMesh m = extrude(o.outline, -5e-3, 5e-3);
      const auto t2 = Clock::now();
      DecompositionOptions opt;
      opt.tooth_layout = tooth_layout(s);
      const ConvexDecomposition d = decompose(o.outline, opt);
      const ConvexPieces3 p = extrude_pieces(d, PrismFrame{}, -5e-3, 5e-3);
      const auto t3 = Clock::now();
      auto ms = [](auto a, auto b) { return std::chrono::duration<double, std::milli>(b - a).count(); };
      t_outline.push_back(ms(t0, t1));
      t_extrude.push_back(ms(t1, t2));
      t_decomp.push_back(ms(t2, t3));
      t_total.push_back(ms(t0, t3));
      pieces = p.pieces.size();
      outline_points = o.outline.outer.points.size();
      for (const Polygon2& h : o.outline.holes) outline_points += h.points.size();
      if (m.triangles.empty()) return 1;
    }
    std::printf("%-8s %8zu %10.2f %10.2f %10.2f %10.2f %8zu\n", s.name.c_str(), outline_points, median(t_outline), median(t_extrude),
                median(t_decomp), median(t_total), pieces);
  }
  return 0;
}
