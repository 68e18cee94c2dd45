// Benchmark and equivalence record of tooth contact on a scenario's own gears: every meshing
// pair of the scenario (sun–planets, planets–ring for the paper's set, the faulty planet
// included) swept kinematically through a full relative planet turn at the simulation's step,
// pressed by −0.5 / 0 / +0.5 / +1 / +2 µm, with the sun shifted by 0 / ±1 µm (the floating sun).
// Prints µs per find_tooth_contacts call; with `--dump FILE` it also writes every contact of the
// sweep (binary, host order), and `--compare A B` reports how two dumps differ: calls whose
// tooth-pair sets differ, and the largest depth, point and normal differences. Used to show
// that a faster contact search returns the same contacts as the one it replaces.
// With `--coherent` each sweep (pair, press, offset) runs through one CoherentToothSearch, as a
// simulation steps a pair: its dump compares with the stateless one's; `--continued` also turns
// its continuation on (CoherentToothSearch::set_continuation).
// Usage: bench_contact_sweep [scenario.yaml=assets/scenarios/paper_dynamics.yaml] [--dump FILE] [--coherent] [--continued]
//                            [--press-offset-um U] (added to every press: a CAD gear's backlash taken up)
//        bench_contact_sweep --compare A B
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "contact/coherent_contact.hpp"
#include "contact/tooth_contact.hpp"
#include "bench/mesh_sweep.hpp"

using namespace gearsim;
using namespace gearsim::physics;
using namespace gearsim::contact;
using Clock = std::chrono::steady_clock;

namespace {

using bench::Record;

int compare(const char* fa, const char* fb) {
  auto load = [](const char* f) {
    std::vector<Record> v;
    std::ifstream in(f, std::ios::binary);
    Record r;
    while (in.read(reinterpret_cast<char*>(&r), sizeof r)) v.push_back(r);
    return v;
  };
  const std::vector<Record> a = load(fa), b = load(fb);
  // Walk both in call order; contacts of one call are sorted by (tooth_a, tooth_b, flank).
  std::size_t i = 0, j = 0, same_bits = 0, matched = 0, only_a = 0, only_b = 0;
  double max_depth = 0, max_rel_depth = 0, max_point = 0, max_normal = 0, max_depth_at = 0, deepest_unmatched = 0;
  // Matched contacts whose depths differ by more than 1e-13, 1e-12, ... 1e-9 m.
  std::size_t above[5] = {};
  while (i < a.size() || j < b.size()) {
    auto key = [](const Record& r) { return std::make_tuple(r.call, r.tooth_a, r.tooth_b, r.flank_a); };
    if (j == b.size() || (i < a.size() && key(a[i]) < key(b[j]))) {
      deepest_unmatched = std::max(deepest_unmatched, a[i].depth);
      ++only_a, ++i;
      continue;
    }
    if (i == a.size() || key(b[j]) < key(a[i])) {
      deepest_unmatched = std::max(deepest_unmatched, b[j].depth);
      ++only_b, ++j;
      continue;
    }
    const Record &x = a[i++], &y = b[j++];
    ++matched;
    if (std::memcmp(&x, &y, sizeof x) == 0) ++same_bits;
    const double dd = std::abs(x.depth - y.depth);
    for (int e = 0; e < 5; ++e) above[e] += dd > 1e-13 * std::pow(10.0, e);
    if (dd > max_depth) max_depth = dd, max_depth_at = x.depth;
    max_rel_depth = std::max(max_rel_depth, dd / std::max(x.depth, 1e-9));
    max_point = std::max(max_point, std::hypot(x.point_x - y.point_x, x.point_y - y.point_y));
    max_normal = std::max(max_normal, std::abs(x.normal_x * y.normal_y - x.normal_y * y.normal_x));
  }
  std::printf("contacts: %zu in A, %zu in B; %zu matched (%zu bit-identical), %zu only in A, %zu only in B\n", a.size(), b.size(), matched,
              same_bits, only_a, only_b);
  std::printf(
      "largest differences of matched contacts: depth %.3e m (at a depth of %.3e m; relative %.2e), "
      "point %.3e m, normal %.3e rad\n",
      max_depth, max_depth_at, max_rel_depth, max_point, max_normal);
  std::printf(
      "depth differences over 1e-13 / 1e-12 / 1e-11 / 1e-10 / 1e-9 m: %zu / %zu / %zu / %zu / %zu; "
      "deepest unmatched contact %.3e m\n",
      above[0], above[1], above[2], above[3], above[4], deepest_unmatched);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 4 && std::string(argv[1]) == "--compare") return compare(argv[2], argv[3]);
  std::string file = std::string(GEARSIM_SOURCE_DIR) + "/assets/scenarios/paper_dynamics.yaml", dump;
  bool coherent = false, continued = false;
  double press_offset_m = 0;  // added to every press: takes up a CAD gear's backlash
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--dump" && i + 1 < argc)
      dump = argv[++i];
    else if (std::string(argv[i]) == "--coherent")
      coherent = true;
    else if (std::string(argv[i]) == "--continued")
      coherent = continued = true;
    else if (std::string(argv[i]) == "--press-offset-um" && i + 1 < argc)
      press_offset_m = 1e-6 * std::stod(argv[++i]);
    else
      file = argv[i];
  }
  bench::MeshSweep sw;
  if (!sw.load(file)) return 1;
  std::ofstream out;
  if (!dump.empty()) out.open(dump, std::ios::binary);
  long calls = 0, contacts = 0;
  std::vector<ToothContact> found;
  CoherentToothSearch::Counts flanks;
  double seconds = 0;
  for (const auto& [ia, ib] : sw.pairs) {
    const bench::SweepGear &ga = sw.gears[static_cast<std::size_t>(ia)], &gb = sw.gears[static_cast<std::size_t>(ib)];
    for (double press : bench::MeshSweep::presses_m)
      for (double shift : bench::MeshSweep::shifts_m) {
        CoherentToothSearch search;
        search.set_continuation(continued);
        for (long i = 0; i < sw.steps; ++i) {
          PlanarPose pa, pb;
          sw.poses(ga, gb, i, press + press_offset_m, shift, &pa, &pb);
          const auto t0 = Clock::now();
          if (coherent)
            search.find(*ga.table, pa, *gb.table, pb, found);
          else
            find_tooth_contacts(*ga.table, pa, *gb.table, pb, found);
          seconds += std::chrono::duration<double>(Clock::now() - t0).count();
          for (const ToothContact& c : found) {
            const Record r = bench::record_of(calls, c);
            if (out) out.write(reinterpret_cast<const char*>(&r), sizeof r);
          }
          contacts += static_cast<long>(found.size());
          ++calls;
        }
        flanks += search.counts();
      }
  }
  std::printf("%s: %zu meshing pairs, %ld calls (%ld steps of %.3g rad each), %.2f contacts/call, %.2f us/call\n", sw.name.c_str(),
              sw.pairs.size(), calls, sw.steps, sw.step_rad, static_cast<double>(contacts) / static_cast<double>(calls),
              1e6 * seconds / static_cast<double>(calls));
  if (coherent)
    std::printf("coherent search: %ld flanks searched in full, %ld tracked, %ld skipped (%.1f %%), %ld renewed, %ld continued\n",
                flanks.searched, flanks.tracked, flanks.skipped,
                100.0 * static_cast<double>(flanks.skipped) /
                    static_cast<double>(flanks.searched + flanks.tracked + flanks.skipped + flanks.renewed),
                flanks.renewed, flanks.continued);
  return 0;
}
