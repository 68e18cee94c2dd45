#include "app/pose_replay.hpp"

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"

namespace gearsim::app {
namespace {

double angle_about_z(const Eigen::Quaterniond& q) {
  const Eigen::Vector3d x = q * Eigen::Vector3d::UnitX();
  return std::atan2(x.y(), x.x());
}

}  // namespace

PoseReplay::PoseReplay(const physics::Scenario& scenario, input::CsvTable state) : s_(scenario), state_(std::move(state)) {
  time_ = state_.column("time_s");
  if (time_.size() < 2) throw InputError(state_.path.string() + ": fewer than two rows, nothing to replay");
  const std::size_t n = s_.bodies.size();
  angle_.assign(n, nullptr);
  parent_.assign(n, -1);
  pivot0_.assign(n, Eigen::Vector3d::Zero());
  angle0_.assign(n, 0.0);
  for (std::size_t b = 0; b < n; ++b) {
    const physics::BodyDef& body = s_.bodies[b];
    angle0_[b] = angle_about_z(body.pose.orientation);
    pivot0_[b] = body.pose.position_m;
    for (const physics::JointDef& j : s_.joints) {
      if (j.body != body.name) continue;
      if (j.axis.normalized().cross(Eigen::Vector3d::UnitZ()).norm() > 1e-9)
        throw InputError(s_.source.string() + ": joint '" + j.name + "': replay needs axes along z");
      angle_[b] = &state_.column(body.name + "_angle_rad");
      pivot0_[b] = j.pivot_m;
      for (std::size_t p = 0; p < n; ++p)
        if (s_.bodies[p].name == j.parent) parent_[b] = static_cast<int>(p);
    }
  }
}

std::vector<Eigen::Isometry3d> PoseReplay::poses(double t) const {
  if (t < time_.front() || t > time_.back())
    throw InputError(state_.path.string() + ": time " + std::to_string(t) + " s is outside the logged " + std::to_string(time_.front()) +
                     "–" + std::to_string(time_.back()) + " s");
  const std::size_t i =
      std::min<std::size_t>(static_cast<std::size_t>(std::upper_bound(time_.begin(), time_.end(), t) - time_.begin()), time_.size() - 1);
  const std::size_t i0 = i == 0 ? 0 : i - 1;
  const double w = time_[i] > time_[i0] ? (t - time_[i0]) / (time_[i] - time_[i0]) : 0.0;
  const std::size_t n = s_.bodies.size();
  // World angle (about z) and pivot of each body, resolved parents first.
  std::vector<double> angle(n, 0.0);
  std::vector<Eigen::Vector3d> pivot(n);
  std::vector<bool> done(n, false);
  auto resolve = [&](auto&& self, std::size_t b) -> void {
    if (done[b]) return;
    double rel = angle0_[b];
    if (angle_[b]) rel = (*angle_[b])[i0] + w * ((*angle_[b])[i] - (*angle_[b])[i0]);
    const int p = parent_[b];
    if (p < 0) {
      angle[b] = rel;
      pivot[b] = pivot0_[b];
    } else {
      self(self, static_cast<std::size_t>(p));
      const auto pp = static_cast<std::size_t>(p);
      angle[b] = angle[pp] + rel;
      // The pivot rides on the parent: fixed in the parent's frame since t = 0.
      const Eigen::AngleAxisd turn(angle[pp] - angle0_[pp], Eigen::Vector3d::UnitZ());
      pivot[b] = pivot[pp] + turn * (pivot0_[b] - pivot0_[pp]);
    }
    done[b] = true;
  };
  std::vector<Eigen::Isometry3d> out(n);
  for (std::size_t b = 0; b < n; ++b) {
    resolve(resolve, b);
    // The body's origin keeps its offset from its pivot in the body frame.
    const Eigen::AngleAxisd turn(angle[b] - angle0_[b], Eigen::Vector3d::UnitZ());
    const Eigen::Vector3d origin = pivot[b] + turn * (s_.bodies[b].pose.position_m - pivot0_[b]);
    out[b] = Eigen::Translation3d(origin) * Eigen::AngleAxisd(angle[b], Eigen::Vector3d::UnitZ());
  }
  return out;
}

}  // namespace gearsim::app
