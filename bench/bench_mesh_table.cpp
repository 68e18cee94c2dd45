// Measurement for issue 18 (speed): how well, and how fast, a gear pair's tooth contacts could be
// read from a table over the mesh cycle instead of searched each step. Not used by the
// simulation. For every meshing pair of a scenario (as bench_contact_sweep) it tabulates the
// stateless search's contacts (and near pairs) over one full turn of the gear whose teeth
// differ (the faulty planet; the other gear's teeth must all be alike), on the line of centres at
// the starting centre distance and the conjugate angle, with second-order Taylor coefficients in
// the two small deviations a run adds: ε, the other gear's turn beyond the conjugate angle, and
// ΔD, the centre distance's change (finite differences of the search's own answers). A pose
// pair is then reduced to (ψ, ε, ΔD) by its line of centres and the contacts read from the two
// samples around ψ (linear in ψ). It sweeps the pairs as bench_contact_sweep does (presses, sun
// shifts; bench/mesh_sweep.hpp), prints per press and shift how far the table's contacts lie from
// the stateless search's, and dumps them in bench_contact_sweep's format (`--compare`). Prints
// build time, memory and ns per call (with the stateless search run between the calls).
// Usage: bench_mesh_table [scenario.yaml] [--samples-per-pitch N] [--dump FILE]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "bench/mesh_sweep.hpp"
#include "contact/tooth_contact.hpp"

using namespace gearsim;
using namespace gearsim::physics;
using namespace gearsim::contact;
using Clock = std::chrono::steady_clock;
using Eigen::Vector2d;

namespace {

constexpr double kTwoPi = 6.283185307179586;

double wrap_angle(double a) { return a - kTwoPi * std::floor(a / kTwoPi); }

// Fields tabulated per contact: depth, the point (x, y) and the normal's angle in the pair frame
// (b's centre at the origin, a's on +x); each with value, ∂ε, ∂D, ∂εε, ∂DD, ∂εD.
constexpr int kFields = 4, kCoefs = 6;
struct Entry {
  int tooth_x = 0, tooth_y = 0;  // tooth of the tabulated gear X, and of Y in the table's pose
  Flank flank_a = Flank::Ccw;
  double c[kFields][kCoefs] = {};
};

struct PairTable {
  bool x_is_a = false;
  double d0 = 0, ratio = 0, psi_y0 = 0, pitch_y = 0, dpsi = 0;
  int teeth_y = 0, samples = 0;
  std::vector<std::vector<Entry>> at;  // per sample of ψ_X over one turn
  long uncovered = 0;  // contacts missing from some of a sample's six evaluations
};

struct Config {
  double psi_x, eps, dd, alpha;
  Vector2d origin;  // b's centre
  int shift_y;  // Y's tooth numbers: actual = table − shift_y (mod teeth)
};

// (ψ_X, ε, ΔD) of a pose pair: the line of centres from b's centre to a's, each gear's angle
// against it.
Config config_of(const PairTable& t, const PlanarPose& pa, const PlanarPose& pb) {
  const Vector2d c = pa.centre_m - pb.centre_m;
  const double alpha = std::atan2(c.y(), c.x());
  const double psi_a = pa.angle_rad - alpha, psi_b = pb.angle_rad - alpha;
  const double psi_x = wrap_angle(t.x_is_a ? psi_a : psi_b), psi_y = t.x_is_a ? psi_b : psi_a;
  const double raw = psi_y - (t.psi_y0 + t.ratio * psi_x);
  const double m = std::nearbyint(raw / t.pitch_y);
  return {psi_x, raw - m * t.pitch_y, c.norm() - t.d0, alpha, pb.centre_m, static_cast<int>(m)};
}

// The poses of the table's frame: b at the origin, a on +x at distance d.
void table_poses(const PairTable& t, double psi_x, double eps, double dd, PlanarPose* pa, PlanarPose* pb) {
  const double psi_y = t.psi_y0 + t.ratio * psi_x + eps;
  pb->centre_m = Vector2d::Zero();
  pa->centre_m = Vector2d(t.d0 + dd, 0);
  pa->angle_rad = t.x_is_a ? psi_x : psi_y;
  pb->angle_rad = t.x_is_a ? psi_y : psi_x;
}

PairTable build(const FlankTable& ta, const PlanarPose& pa0, const FlankTable& tb, const PlanarPose& pb0, int per_pitch) {
  PairTable t;
  t.x_is_a = ta.distinct_teeth() > 1;
  const FlankTable &tx = t.x_is_a ? ta : tb, &ty = t.x_is_a ? tb : ta;
  if (ty.distinct_teeth() > 1) throw std::runtime_error("both gears have distinct teeth: not in this measurement");
  const bool internal = ta.internal() || tb.internal();
  // Rolling: Y turns by ∓z_X/z_Y per turn of X (external: opposite senses; internal: the same).
  t.ratio = (internal ? 1.0 : -1.0) * static_cast<double>(tx.teeth()) / ty.teeth();
  t.pitch_y = kTwoPi / ty.teeth();
  t.teeth_y = ty.teeth();
  const Vector2d c = pa0.centre_m - pb0.centre_m;
  t.d0 = c.norm();
  const double alpha = std::atan2(c.y(), c.x());
  const double psi_x0 = (t.x_is_a ? pa0.angle_rad : pb0.angle_rad) - alpha,
               psi_y_start = (t.x_is_a ? pb0.angle_rad : pa0.angle_rad) - alpha;
  t.psi_y0 = psi_y_start - t.ratio * psi_x0;  // conjugate at the start pose
  t.samples = tx.teeth() * per_pitch;
  t.dpsi = kTwoPi / t.samples;
  t.at.resize(static_cast<std::size_t>(t.samples));
  const double r_y = 0.5 * (ty.r_min_m() + ty.r_max_m());
  const double h = 0.5e-6 / r_y, g = 0.5e-6;  // ε and ΔD steps: 0.5 µm at Y's mid-tooth radius
  const double offs[6][2] = {{0, 0}, {h, 0}, {-h, 0}, {0, g}, {0, -g}, {h, g}};
  std::vector<ToothContact> found, near;
  for (int k = 0; k < t.samples; ++k) {
    // Per contact key, the six evaluations' fields.
    std::map<std::tuple<int, int, int>, std::array<std::array<double, kFields>, 6>> got;
    std::map<std::tuple<int, int, int>, int> seen;
    for (int e = 0; e < 6; ++e) {
      PlanarPose pa, pb;
      table_poses(t, k * t.dpsi, offs[e][0], offs[e][1], &pa, &pb);
      find_tooth_contacts(ta, pa, tb, pb, found, &near);
      for (const std::vector<ToothContact>* list : {&found, &near})
        for (const ToothContact& ct : *list) {
          const auto key = std::make_tuple(ct.tooth_a, ct.tooth_b, static_cast<int>(ct.flank_a));
          got[key][static_cast<std::size_t>(e)] = {ct.depth_m, ct.point_m.x(), ct.point_m.y(),
                                                   std::atan2(ct.normal_on_b.y(), ct.normal_on_b.x())};
          seen[key] |= 1 << e;
        }
    }
    for (const auto& [key, v] : got) {
      if (seen[key] != 63) {
        ++t.uncovered;
        continue;
      }
      Entry en;
      en.tooth_x = t.x_is_a ? std::get<0>(key) : std::get<1>(key);
      en.tooth_y = t.x_is_a ? std::get<1>(key) : std::get<0>(key);
      en.flank_a = static_cast<Flank>(std::get<2>(key));
      for (int f = 0; f < kFields; ++f) {
        double val[6];
        for (int e = 0; e < 6; ++e) val[e] = v[static_cast<std::size_t>(e)][static_cast<std::size_t>(f)];
        if (f == 3)  // angles: unwrapped about the first
          for (int e = 1; e < 6; ++e) val[e] = val[0] + std::remainder(val[e] - val[0], kTwoPi);
        const double fe = (val[1] - val[2]) / (2 * h), fee = (val[1] - 2 * val[0] + val[2]) / (h * h);
        const double fd = (val[3] - val[4]) / (2 * g), fdd = (val[3] - 2 * val[0] + val[4]) / (g * g);
        const double fed = (val[5] - val[0] - fe * h - fd * g - 0.5 * fee * h * h - 0.5 * fdd * g * g) / (h * g);
        en.c[f][0] = val[0], en.c[f][1] = fe, en.c[f][2] = fd, en.c[f][3] = fee, en.c[f][4] = fdd, en.c[f][5] = fed;
      }
      t.at[static_cast<std::size_t>(k)].push_back(en);
    }
  }
  return t;
}

// The table's contacts (depth > 0) at a pose pair, in the stateless search's order.
void read(const PairTable& t, const PlanarPose& pa, const PlanarPose& pb, std::vector<ToothContact>& out, long& one_sided) {
  out.clear();
  const Config cf = config_of(t, pa, pb);
  const double s = cf.psi_x / t.dpsi;
  const int k0 = std::min(static_cast<int>(s), t.samples - 1), k1 = (k0 + 1) % t.samples;
  const double w = s - k0;
  const std::vector<Entry>&e0 = t.at[static_cast<std::size_t>(k0)], &e1 = t.at[static_cast<std::size_t>(k1)];
  const double ca = std::cos(cf.alpha), sa = std::sin(cf.alpha);
  for (const Entry& u : e0) {
    const Entry* v = nullptr;
    for (const Entry& x : e1)
      if (x.tooth_x == u.tooth_x && x.tooth_y == u.tooth_y && x.flank_a == u.flank_a) v = &x;
    if (!v) {
      ++one_sided;
      continue;
    }
    double f[kFields];
    for (int i = 0; i < kFields; ++i) {
      double c[kCoefs];
      for (int j = 0; j < kCoefs; ++j) c[j] = (1 - w) * u.c[i][j] + w * v->c[i][j];
      f[i] = c[0] + c[1] * cf.eps + c[2] * cf.dd + 0.5 * c[3] * cf.eps * cf.eps + 0.5 * c[4] * cf.dd * cf.dd + c[5] * cf.eps * cf.dd;
    }
    if (!(f[0] > 0)) continue;
    ToothContact ct;
    int ty = ((u.tooth_y - cf.shift_y) % t.teeth_y + t.teeth_y) % t.teeth_y;
    ct.tooth_a = t.x_is_a ? u.tooth_x : ty;
    ct.tooth_b = t.x_is_a ? ty : u.tooth_x;
    ct.flank_a = u.flank_a;
    ct.depth_m = f[0];
    ct.point_m = cf.origin + Vector2d(ca * f[1] - sa * f[2], sa * f[1] + ca * f[2]);
    ct.normal_on_b = Vector2d(std::cos(f[3] + cf.alpha), std::sin(f[3] + cf.alpha));
    out.push_back(ct);
  }
  std::sort(out.begin(), out.end(), [](const ToothContact& x, const ToothContact& y) {
    return std::make_tuple(x.tooth_a, x.tooth_b, static_cast<int>(x.flank_a)) <
           std::make_tuple(y.tooth_a, y.tooth_b, static_cast<int>(y.flank_a));
  });
}

}  // namespace

int main(int argc, char** argv) {
  std::string file = std::string(GEARSIM_SOURCE_DIR) + "/assets/scenarios/paper_dynamics.yaml", dump;
  int per_pitch = 64;
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--dump" && i + 1 < argc)
      dump = argv[++i];
    else if (std::string(argv[i]) == "--samples-per-pitch" && i + 1 < argc)
      per_pitch = std::stoi(argv[++i]);
    else
      file = argv[i];
  }
  bench::MeshSweep sw;
  if (!sw.load(file)) return 1;
  std::ofstream out;
  if (!dump.empty()) out.open(dump, std::ios::binary);
  long calls = 0, contacts = 0, one_sided = 0, uncovered = 0;
  std::size_t entries = 0;
  double build_s = 0, read_s = 0;
  std::vector<ToothContact> found, reference;
  struct Err {
    long n = 0, over_nm = 0;
    double worst = 0, missing = 0;
  };
  std::map<std::pair<double, double>, Err> errs;
  for (const auto& [ia, ib] : sw.pairs) {
    const bench::SweepGear &ga = sw.gears[static_cast<std::size_t>(ia)], &gb = sw.gears[static_cast<std::size_t>(ib)];
    const auto t0 = Clock::now();
    const PairTable table = build(*ga.table, ga.pose, *gb.table, gb.pose, per_pitch);
    build_s += std::chrono::duration<double>(Clock::now() - t0).count();
    uncovered += table.uncovered;
    for (const auto& v : table.at) entries += v.size();
    for (double press : bench::MeshSweep::presses_m)
      for (double shift : bench::MeshSweep::shifts_m)
        for (long i = 0; i < sw.steps; ++i) {
          PlanarPose pa, pb;
          sw.poses(ga, gb, i, press, shift, &pa, &pb);
          const auto t1 = Clock::now();
          read(table, pa, pb, found, one_sided);
          read_s += std::chrono::duration<double>(Clock::now() - t1).count();
          for (const ToothContact& c : found) {
            const bench::Record r = bench::record_of(calls, c);
            if (out) out.write(reinterpret_cast<const char*>(&r), sizeof r);
          }
          contacts += static_cast<long>(found.size());
          ++calls;
          // Against the stateless search, per press and shift.
          find_tooth_contacts(*ga.table, pa, *gb.table, pb, reference);
          Err& er = errs[{press, shift}];
          for (const ToothContact& r : reference) {
            const ToothContact* m = nullptr;
            for (const ToothContact& c : found)
              if (c.tooth_a == r.tooth_a && c.tooth_b == r.tooth_b && c.flank_a == r.flank_a) m = &c;
            if (!m) {
              er.missing = std::max(er.missing, r.depth_m);
              continue;
            }
            const double d = std::abs(m->depth_m - r.depth_m);
            er.worst = std::max(er.worst, d);
            er.over_nm += d > 1e-9;
            ++er.n;
          }
        }
  }
  for (const auto& [k, er] : errs)
    std::printf("press %+.1f um shift %+.1f um: %ld contacts, %ld over 1 nm, worst %.3g m, deepest missing %.3g m\n", 1e6 * k.first,
                1e6 * k.second, er.n, er.over_nm, er.worst, er.missing);
  std::printf("%s: %zu pairs, %d samples per pitch of the tabulated gear; build %.2f s, %zu entries (%.1f MiB)\n", sw.name.c_str(),
              sw.pairs.size(), per_pitch, build_s, entries, static_cast<double>(entries * sizeof(Entry)) / (1 << 20));
  std::printf("%ld calls, %.2f contacts/call, %.0f ns/call; %ld contacts read from one sample only, %ld keys not in all six evaluations\n",
              calls, static_cast<double>(contacts) / static_cast<double>(calls), 1e9 * read_s / static_cast<double>(calls), one_sided,
              uncovered);
  return 0;
}
