// Benchmark: tooth contact alone, the paper's sun–planet pair turned through two pitches in
// simulation-sized steps with the mesh pressed 1 µm (a loaded pair); microseconds per call and
// nanoseconds per first-order depth probe of FlankTable.
// Usage: bench_tooth_contact [steps=4000]
#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "geometry/gear_profile.hpp"
#include "geometry/planetary.hpp"
#include "contact/tooth_contact.hpp"

using namespace gearsim;
using namespace gearsim::contact;
using Clock = std::chrono::steady_clock;

namespace {

GearSpec gear(int teeth, bool internal) {
  GearSpec s;
  s.name = std::string("g") + std::to_string(teeth);  // not "g" + a temporary: GCC 12 -Wrestrict false positive
  s.teeth = teeth;
  s.module_m = 1e-3;
  s.face_width_m = 10e-3;
  s.chordal_deviation_m = 0.5e-6;
  if (internal) {
    s.kind = GearKind::Internal;
    s.rim_diameter_m = 110e-3;
  } else {
    s.bore_diameter_m = 8e-3;
  }
  return s;
}

FlankTable table_of(const GearSpec& s) {
  const GearOutline o = make_gear_outline(s);
  const Polygon2& loop = s.kind == GearKind::External ? o.outline.outer : o.outline.holes.front();
  return FlankTable(loop, {s.teeth, s.tooth0_angle_rad}, s.kind == GearKind::Internal, 4096);
}

}  // namespace

int main(int argc, char** argv) {
  const int steps = argc > 1 ? std::atoi(argv[1]) : 4000;
  const GearSpec sun = gear(24, false), planet = gear(36, false), ring = gear(96, true);
  const FlankTable ts = table_of(sun), tp = table_of(planet);
  const PlanetaryGeometry g = analyse_planetary({sun, planet, ring, 3});
  const PlanarPose planet0{{g.centre_distance_m, 0.0}, g.placements[0].spin_angle_rad};
  const double press = 1e-6 / (0.5 * 24e-3 * std::cos(20.0 * 3.141592653589793 / 180));
  long contacts = 0;
  const auto t_calls = Clock::now();
  for (int i = 0; i < steps; ++i) {
    const double roll = i * 2.1e-3;  // sun rad per step: 104.7 rad/s × 2e-5 s
    PlanarPose s{{0, 0}, roll + press}, p = planet0;
    p.angle_rad -= roll * 24.0 / 36.0;
    contacts += static_cast<long>(find_tooth_contacts(ts, s, tp, p).size());
  }
  const double us = std::chrono::duration<double, std::micro>(Clock::now() - t_calls).count() / steps;
  std::printf("sun-planet find_tooth_contacts: %.2f us/call, %.2f contacts/call\n", us, static_cast<double>(contacts) / steps);
  // Planet–ring, in the carrier frame: the ring turns by −φ, the planet by −φ·96/36 (same sense).
  const FlankTable tr = table_of(ring);
  const PlanarPose ring0{{0, 0}, g.ring_angle_rad};
  contacts = 0;
  const auto t_ring = Clock::now();
  for (int i = 0; i < steps; ++i) {
    const double phi = i * 4.2e-4;  // ring rad per step relative to the carrier: 20.94 rad/s × 2e-5 s
    PlanarPose r = ring0, p = planet0;
    r.angle_rad -= phi;
    p.angle_rad -= phi * 96.0 / 36.0 + 1e-6 / 17e-3;
    contacts += static_cast<long>(find_tooth_contacts(tp, p, tr, r).size());
  }
  const double us_ring = std::chrono::duration<double, std::micro>(Clock::now() - t_ring).count() / steps;
  std::printf("planet-ring find_tooth_contacts: %.2f us/call, %.2f contacts/call\n", us_ring, static_cast<double>(contacts) / steps);
  // The probe alone: points swept across a tooth space of the planet.
  const int n = 1 << 20;
  double sink = 0;
  const auto t0 = Clock::now();
  for (int i = 0; i < n; ++i) {
    const double a = (i % 4096) * 1e-4, r = 17.2e-3 + (i % 977) * 1.9e-6;
    sink += tp.probe_depth({r * std::cos(a), r * std::sin(a)}).depth_m;
  }
  const double ns = std::chrono::duration<double, std::nano>(Clock::now() - t0).count() / n;
  std::printf("FlankTable::probe_depth: %.1f ns/call (incl. sincos of the test point) [%g]\n", ns, sink);
  return 0;
}
