#include "sim/sensor_log.hpp"

#include <cmath>
#include <iomanip>
#include <numbers>

#include "analysis/decimation_filter.hpp"
#include "analysis/planet_separation.hpp"
#include "core/errors.hpp"
#include "core/number_text.hpp"
#include "core/output_file.hpp"

namespace gearsim::sim {
namespace {

// Whole steps per sensor sample (the reader checked it is whole).
long steps_per_sample(const physics::Scenario& s) { return std::lround(1.0 / (s.sensors.front().sample_rate_hz * s.solver.time_step_s)); }

}  // namespace

double planet_pass_window(const Eigen::Vector2d& point, const Eigen::Vector2d& centre, double sensor_angle_rad, double width_rad) {
  const Eigen::Vector2d r = point - centre;
  return planet_pass_hann(std::atan2(r.y(), r.x()) - sensor_angle_rad, width_rad);
}

SensorLog::SensorLog(const std::filesystem::path& dir, const physics::Scenario& s)
    : file_(dir / "sensors.csv"), scenario_(s), noise_(s.seed ^ 0x5e4504c5ull) {
  GEARSIM_CHECK(!s.sensors.empty(), "a sensor log without sensors");
  const double fs_step = 1.0 / s.solver.time_step_s;
  for (const physics::SensorDef& d : s.sensors) {
    Channel c{&d, Eigen::Vector2d::Zero(), {}, Resonator(d.resonance_hz, d.damping_ratio, d.effective_mass_kg, fs_step)};
    for (const physics::BodyDef& b : s.bodies)
      if (b.name == d.body) c.centre = b.pose.position_m.head<2>();
    channels_.push_back(std::move(c));
  }
}

void SensorLog::on_start(const physics::World& world) {
  out_ = std::make_unique<OutputFile>(file_, Durability::Record);
  *out_ << std::setprecision(17) << "time_s";
  for (Channel& c : channels_) {
    *out_ << ',' << c.def->name << "_acceleration_m_s2";
    c.on_body.clear();
    for (const physics::GearPairInfo& p : world.gear_pairs()) c.on_body.push_back(p.body_a == c.def->body || p.body_b == c.def->body);
  }
  *out_ << '\n';
  const long every = steps_per_sample(scenario_);
  const double fs_step = 1.0 / scenario_.solver.time_step_s;
  if (every >= 2) decimator_.emplace(design_decimation_filter(fs_step, fs_step / static_cast<double>(every)), channels_.size(), 0.0);
  push(world);  // the world at rest, t = 0 (not a row)
}

void SensorLog::push(const physics::World& world) {
  row_.assign(channels_.size(), 0.0);
  for (std::size_t s = 0; s < channels_.size(); ++s) {
    Channel& c = channels_[s];
    double force = 0;
    for (const physics::ContactSample& cs : world.contacts()) {
      const std::size_t p = static_cast<std::size_t>(cs.pair);
      const double gain = c.on_body[p] ? planet_pass_window(cs.geometry.point_m, c.centre, c.def->angle_rad, c.def->window_width_rad)
                                       : c.def->other_meshes_weight;
      force += gain * cs.normal_force_N;
    }
    row_[s] = c.mode.step(force);
  }
  if (!decimator_) {
    if (world.steps() > 0) write({world.time_s(), row_});
    return;
  }
  if (const std::optional<DecimatedRow> out = decimator_->push(row_)) write(*out);
}

void SensorLog::on_step(const physics::World& world) { push(world); }

std::vector<std::string> SensorLog::names() const {
  std::vector<std::string> n;
  for (const physics::SensorDef& d : scenario_.sensors) n.push_back(d.name);
  return n;
}

void SensorLog::write(const DecimatedRow& row) {
  if (row.time_s <= 0) return;  // t = 0: the world at rest, not a row
  std::string& text = row_text_;
  text.clear();
  append_number(text, row.time_s);
  for (std::size_t s = 0; s < channels_.size(); ++s) {
    const double noise =
        channels_[s].def->noise_rms_m_s2 > 0 ? std::normal_distribution<double>(0.0, channels_[s].def->noise_rms_m_s2)(noise_) : 0.0;
    text += ',';
    append_number(text, row.values[s] + noise);
  }
  text += '\n';
  out_->write(text.data(), static_cast<std::streamsize>(text.size()));
}

void SensorLog::on_stop(const physics::World&) {
  if (decimator_)
    for (const DecimatedRow& out : decimator_->finish()) write(out);
  out_->commit();
}

bool SensorLog::write_failed() const { return out_ && out_->failed(); }

}  // namespace gearsim::sim
