#include "linear/mesh_average.hpp"

#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

#include "core/errors.hpp"

namespace gearsim::linear {
namespace {

double cross(const Eigen::Vector2d& r, const Eigen::Vector2d& n) { return r.x() * n.y() - r.y() * n.x(); }

// At most this many mesh positions per pair (a long hunting period is sampled sparser).
constexpr long kMaxSamples = 1 << 16;
// Positions are pressed this many times the deflection past first touch (then trimmed back).
constexpr double kPressFactor = 10;

struct Placed {
  contact::PlanarPose a, b;
};

// The loaded contacts at one placement: those whose force turns the driven gear in its sense.
class LoadedContacts {
 public:
  LoadedContacts(const MeshGear& a, const MeshGear& b, bool driven_is_b, int sense)
      : a_(a), b_(b), driven_is_b_(driven_is_b), sense_(sense) {}

  const std::vector<contact::ToothContact>& at(const Placed& p) {
    contact::find_tooth_contacts(*a_.flanks, p.a, *b_.flanks, p.b, all_);
    loaded_.clear();
    for (const contact::ToothContact& c : all_) {
      // The force on a is +n·F, on b −n·F (normal_on_b points from b toward a).
      const double torque = driven_is_b_ ? cross(c.point_m - p.b.centre_m, -c.normal_on_b) : cross(c.point_m - p.a.centre_m, c.normal_on_b);
      if (torque * sense_ > 0) loaded_.push_back(c);
    }
    return loaded_;
  }
  double deepest(const Placed& p) {
    double d = -std::numeric_limits<double>::infinity();
    for (const contact::ToothContact& c : at(p)) d = std::max(d, c.depth_m);
    return d;
  }

 private:
  const MeshGear &a_, &b_;
  bool driven_is_b_;
  int sense_;
  std::vector<contact::ToothContact> all_, loaded_;
};

// The lag (rad) at which the loaded flanks of the placement `at(lag)` are pressed `depth_m` deep:
// bracketed from the ideal position outward, then bisected.
template <class Excess>
double lag_for(Excess excess, double pitch_driven, int teeth_a, int teeth_b) {
  double step = 1e-3 * pitch_driven, hi = 0;
  while (excess(hi) < 0) {
    hi += step, step *= 2;
    if (hi > 0.25 * pitch_driven)
      throw InputError("the loaded flanks never touch within a quarter pitch of the ideal position (gear teeth " + std::to_string(teeth_a) +
                       " and " + std::to_string(teeth_b) + ")");
  }
  step = 1e-3 * pitch_driven;
  double lo = hi - step;
  while (excess(lo) >= 0) {
    lo -= step, step *= 2;
    GEARSIM_CHECK(lo > -0.5 * pitch_driven, "a mesh's loaded flanks touch however far the driven gear is turned back");
  }
  for (int it = 0; it < 60 && hi - lo > 1e-15; ++it) {
    const double mid = 0.5 * (lo + hi);
    (excess(mid) < 0 ? lo : hi) = mid;
  }
  return hi;
}

}  // namespace

MeshAverage average_mesh(const MeshGear& a, const MeshGear& b, const physics::MeshStiffnessModel& model, bool driven_is_b, int driven_sense,
                         int phases, double deflection_m) {
  GEARSIM_CHECK(a.flanks && b.flanks && phases > 0 && deflection_m > 0, "average_mesh needs two gears, phases and a deflection");
  const bool internal = a.flanks->internal() || b.flanks->internal();
  const int za = a.flanks->teeth(), zb = b.flanks->teeth();
  // b turns −z_a/z_b as fast as a (two external gears), +z_a/z_b inside a ring.
  const double ratio = (internal ? 1.0 : -1.0) * za / static_cast<double>(zb);
  const double pitch_driven = (driven_is_b ? b : a).flanks->pitch_angle_rad();
  LoadedContacts loaded(a, b, driven_is_b, driven_sense);
  // Every tooth of a meets every tooth of b once in lcm(z_a, z_b) pitches (the hunting period):
  // sampled over all of it, so that a single flawed tooth weighs what it weighs in a long run.
  const long hunting = std::lcm(static_cast<long>(za), static_cast<long>(zb));
  const long samples = std::min<long>(static_cast<long>(phases) * hunting, std::max<long>(phases, kMaxSamples));
  auto placed_at = [&](double phi, double lag) {
    Placed p{a.pose, b.pose};
    p.a.angle_rad += phi;
    p.b.angle_rad += ratio * phi;
    // The driven gear turned back against its load by `lag`: its loaded flanks press in.
    (driven_is_b ? p.b : p.a).angle_rad -= driven_sense * lag;
    return p;
  };
  // Where the flanks first touch at the start, and how fast they press in per radian of lag.
  const double touch = lag_for([&](double lag) { return loaded.deepest(placed_at(0, lag)); }, pitch_driven, za, zb);
  const double per_rad = loaded.deepest(placed_at(0, touch + 1e-4 * pitch_driven)) / (1e-4 * pitch_driven);
  GEARSIM_CHECK(per_rad > 0, "a mesh's loaded flanks do not press in as the driven gear lags");
  // Each position pressed well past its deepest pair's deflection: the pairs within `deflection_m`
  // of the deepest are those loaded at that deflection (rigid teeth approach alike).
  const double press_rad = touch + (kPressFactor * deflection_m) / per_rad;
  MeshAverage avg;
  avg.min_N_per_m = std::numeric_limits<double>::infinity();
  std::vector<double> k;
  std::vector<char> active;
  std::vector<contact::ToothContact> in_load;
  Eigen::Vector2d normal_sum = Eigen::Vector2d::Zero();
  Eigen::Matrix<double, 6, 1> g_sum = Eigen::Matrix<double, 6, 1>::Zero();
  for (long i = 0; i < samples; ++i) {
    const double phi = a.flanks->pitch_angle_rad() * static_cast<double>(hunting) * static_cast<double>(i) / static_cast<double>(samples);
    Placed at = placed_at(phi, press_rad);
    double deepest = loaded.deepest(at);
    if (!(deepest >= deflection_m)) {
      // A flawed tooth alone in the mesh: find this position's own touch.
      at = placed_at(phi, lag_for([&](double lag) { return loaded.deepest(placed_at(phi, lag)) - deflection_m; }, pitch_driven, za, zb));
      deepest = loaded.deepest(at);
    }
    in_load.clear();
    for (contact::ToothContact c : loaded.at(at)) {
      c.depth_m -= deepest - deflection_m;
      if (c.depth_m > 0) in_load.push_back(c);
    }
    physics::tooth_pair_stiffnesses(model, in_load, model.table_on_a ? at.a : at.b, k, active);
    double sum = 0;
    for (std::size_t c = 0; c < in_load.size(); ++c) {
      if (!active[c]) continue;
      const Eigen::Vector2d& n = in_load[c].normal_on_b;
      Eigen::Matrix<double, 6, 1> g;
      g << n.x(), n.y(), cross(in_load[c].point_m - a.centre_of_mass_m, n), -n.x(), -n.y(),
          -cross(in_load[c].point_m - b.centre_of_mass_m, n);
      g_sum += k[c] * g;
      sum += k[c];
      normal_sum += k[c] * n;
      avg.mean_pairs += 1;
    }
    avg.mean_N_per_m += sum;
    avg.min_N_per_m = std::min(avg.min_N_per_m, sum);
    avg.max_N_per_m = std::max(avg.max_N_per_m, sum);
  }
  const double n = static_cast<double>(samples);
  // One spring along the mean line of action: the stiffness-weighted mean of the contacts'
  // directions and lever arms (a rank-one mesh, as lumped models have it). Σ k g gᵀ itself would
  // add stiffness across the line from the scatter of the flank tables' normals (~1e-4 rad),
  // enough to give a train's free rotation a spurious frequency of a few Hz.
  GEARSIM_CHECK(avg.mean_N_per_m > 0, "a mesh whose loaded flanks never carry load");
  Eigen::Matrix<double, 6, 1> g = g_sum / avg.mean_N_per_m;
  const double along = g.head<2>().norm();
  g.head<2>() /= along, g.segment<2>(3) /= along;
  avg.mean_N_per_m /= n;
  avg.stiffness = avg.mean_N_per_m * g * g.transpose();
  avg.mean_pairs /= n;
  avg.mean_normal_on_b = normal_sum.normalized();
  avg.samples = samples;
  return avg;
}

}  // namespace gearsim::linear
