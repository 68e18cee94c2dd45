#include "sim/csv_logs.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "core/errors.hpp"
#include "core/number_text.hpp"
#include "core/output_file.hpp"
#include "sim/simulate.hpp"

namespace gearsim::sim {
namespace {

std::unique_ptr<OutputFile> open_log(const std::filesystem::path& p) {
  auto f = std::make_unique<OutputFile>(p, Durability::Record);
  *f << std::setprecision(17);
  return f;
}

}  // namespace

CsvLogs::CsvLogs(const std::filesystem::path& dir, const physics::Scenario& scenario) : dir_(dir), scenario_(scenario) {
  if (scenario.transmission) {
    te_in_ = body_of_joint(scenario, scenario.transmission->input_joint);
    te_out_ = body_of_joint(scenario, scenario.transmission->output_joint);
  }
  const double dt = scenario.solver.time_step_s;
  every_ = output_interval_steps(scenario);
  // The output rate is the one the samples are taken at: every_ whole steps.
  if (every_ >= 2) filter_ = design_decimation_filter(1.0 / dt, 1.0 / (static_cast<double>(every_) * dt));
}

// The filter's channels: every pair's summed normal force, then the transmission error if any.
std::vector<double> CsvLogs::filtered_channels(const physics::World& world) const {
  std::vector<double> f(pairs_, 0.0);
  for (const physics::ContactSample& c : world.contacts()) f[static_cast<std::size_t>(c.pair)] += c.normal_force_N;
  if (scenario_.transmission) f.push_back(transmission_error_rad(world));
  return f;
}

double CsvLogs::transmission_error_rad(const physics::World& world) const {
  return world.bodies()[static_cast<std::size_t>(te_in_)].angle_rad -
         scenario_.transmission->ratio * world.bodies()[static_cast<std::size_t>(te_out_)].angle_rad - assembly_phase_rad_;
}

void CsvLogs::on_start(const physics::World& world) {
  // The transmission error of the start poses: the assembly phase, removed from every sample.
  assembly_phase_rad_ = 0;
  if (scenario_.transmission) assembly_phase_rad_ = transmission_error_rad(world);
  state_ = open_log(dir_ / "state.csv");
  contacts_ = open_log(dir_ / "contacts.csv");
  pairs_ = world.gear_pairs().size();
  *state_ << "time_s";
  for (const physics::BodyState& b : world.bodies()) *state_ << ',' << b.name << "_angle_rad," << b.name << "_speed_rad_s";
  if (scenario_.transmission) *state_ << ",te_rad,te_point_rad";
  // Bodies on a bearing to the ground: their centre's displacement from its start (what a
  // sensor on the housing at that bearing sees), after every other column.
  moving_.clear();
  for (const physics::JointDef& j : scenario_.joints)
    if (j.bearing && !j.bearing->radially_rigid && j.parent == "ground")
      for (std::size_t i = 0; i < world.bodies().size(); ++i)
        if (world.bodies()[i].name == j.body) {
          moving_.push_back({i, world.bodies()[i].position_m});
          *state_ << ',' << j.body << "_dx_m," << j.body << "_dy_m";
        }
  // Bodies on a bearing on a body that turns about the ground (planets on their carrier): the
  // centre's displacement from its pin, radial and tangential in the carrier's frame.
  carried_.clear();
  auto index_of = [&](const std::string& name) {
    for (std::size_t i = 0; i < world.bodies().size(); ++i)
      if (world.bodies()[i].name == name) return static_cast<long>(i);
    return -1L;
  };
  for (const physics::JointDef& j : scenario_.joints) {
    if (!j.bearing || j.bearing->radially_rigid || j.parent == "ground") continue;
    bool parent_on_ground = false;
    for (const physics::JointDef& pj : scenario_.joints)
      parent_on_ground = parent_on_ground || (pj.body == j.parent && pj.parent == "ground");
    const long b = index_of(j.body), p = index_of(j.parent);
    if (!parent_on_ground || b < 0 || p < 0) continue;
    const auto bi = static_cast<std::size_t>(b), pi = static_cast<std::size_t>(p);
    carried_.push_back({bi, pi, world.bodies()[pi].angle_rad, world.bodies()[bi].position_m - world.bodies()[pi].position_m,
                        world.bodies()[pi].position_m});
    *state_ << ',' << j.body << "_dr_m," << j.body << "_dt_m";
  }
  *state_ << '\n';
  *contacts_ << "time_s";
  for (const physics::GearPairInfo& p : world.gear_pairs()) {
    const std::string n = p.body_a + "__" + p.body_b;
    *contacts_ << ',' << n << "_force_N," << n << "_force_point_N," << n << "_tooth_pairs," << n << "_max_depth_um";
  }
  *contacts_ << '\n';
  // The filter's input starts at t = 0 (the world at rest, before the first step), so that its
  // outputs fall on the sample times j/f_out; output 0 (t = 0) is not a row.
  const std::size_t channels = pairs_ + (scenario_.transmission ? 1 : 0);
  if (filter_ && channels > 0) {
    decimator_.emplace(*filter_, channels, 0.0);
    if (decimator_->push(filtered_channels(world))) GEARSIM_CHECK(false, "no output before the filter's half-length");
  }
}

void CsvLogs::on_step(const physics::World& world) {
  if (!decimator_) return;
  if (const std::optional<DecimatedRow> out = decimator_->push(filtered_channels(world))) write_ready(*out);
}

CsvLogs::PointRow CsvLogs::point_row(const physics::World& world, long sample) const {
  PointRow r{
      sample, world.time_s(), std::vector<double>(pairs_, 0.0), std::vector<double>(pairs_, 0.0), std::vector<int>(pairs_, 0), 0.0, {}, {}};
  for (const physics::ContactSample& c : world.contacts()) {
    const std::size_t p = static_cast<std::size_t>(c.pair);
    r.force_N[p] += c.normal_force_N;
    r.depth_um[p] = std::max(r.depth_um[p], c.geometry.depth_m);
    ++r.tooth_pairs[p];
  }
  for (double& d : r.depth_um) d *= 1e6;
  return r;
}

void CsvLogs::on_sample(const physics::World& world) {
  const long sample = world.steps() % every_ == 0 ? world.steps() / every_ : -1;
  PointRow row = point_row(world, sample);
  // The state row's text around its transmission error, which waits for the filter with the forces.
  std::string& head = row.state_head;
  std::string& tail = row.state_tail;
  const auto field = [](std::string& text, double v) {
    text += ',';
    append_number(text, v);
  };
  append_number(head, world.time_s());
  for (const physics::BodyState& b : world.bodies()) field(head, b.angle_rad), field(head, b.speed_rad_s);
  if (scenario_.transmission) row.te_rad = transmission_error_rad(world);
  for (const auto& [i, start] : moving_) {
    const Eigen::Vector3d d = world.bodies()[i].position_m - start;
    field(tail, d.x()), field(tail, d.y());
  }
  for (const Carried& c : carried_) {
    const physics::BodyState &b = world.bodies()[c.body], &p = world.bodies()[c.parent];
    // The pin: where the carrier's turn since the start has taken the body's start offset.
    const Eigen::Vector3d pin = p.position_m + Eigen::AngleAxisd(p.angle_rad - c.parent_angle0, Eigen::Vector3d::UnitZ()) * c.offset0;
    const Eigen::Vector3d er = (pin - p.position_m).normalized(), et = Eigen::Vector3d::UnitZ().cross(er);
    const Eigen::Vector3d d = b.position_m - pin;
    field(tail, d.dot(er)), field(tail, d.dot(et));
  }
  if (!decimator_)
    write_row(row, filtered_point(row));  // every step a sample, or nothing to filter
  else
    pending_.push_back(std::move(row));
}

// A row's point samples in the filter's channel order: what a row without a filtered value carries.
std::vector<double> CsvLogs::filtered_point(const PointRow& row) const {
  std::vector<double> v = row.force_N;
  if (scenario_.transmission) v.push_back(row.te_rad);
  return v;
}

void CsvLogs::write_ready(const DecimatedRow& out) {
  const long j = std::lround(out.time_s * filter_->output_rate_hz);
  if (j == 0) return;  // t = 0: not a row
  GEARSIM_CHECK(!pending_.empty() && pending_.front().sample == j, "filtered output " + std::to_string(j) + " without its sample row");
  write_row(pending_.front(), out.values);
  pending_.pop_front();
}

void CsvLogs::write_row(const PointRow& row, const std::vector<double>& filtered) {
  std::string& text = row_text_;
  text = row.state_head;
  if (scenario_.transmission) {
    text += ',';
    append_number(text, filtered[pairs_]);
    text += ',';
    append_number(text, row.te_rad);
  }
  text += row.state_tail;
  text += '\n';
  state_->write(text.data(), static_cast<std::streamsize>(text.size()));
  text.clear();
  append_number(text, row.time_s);
  for (std::size_t p = 0; p < pairs_; ++p) {
    text += ',';
    append_number(text, filtered[p]);
    text += ',';
    append_number(text, row.force_N[p]);
    text += ',';
    append_number(text, static_cast<long long>(row.tooth_pairs[p]));
    text += ',';
    append_number(text, row.depth_um[p]);
  }
  text += '\n';
  contacts_->write(text.data(), static_cast<std::streamsize>(text.size()));
}

void CsvLogs::on_stop(const physics::World&) {
  if (decimator_) {
    for (const DecimatedRow& out : decimator_->finish()) write_ready(out);
    // A stop between samples: its row, point samples throughout.
    for (const PointRow& row : pending_) {
      GEARSIM_CHECK(row.sample < 0, "sample row " + std::to_string(row.sample) + " left without its filtered force");
      write_row(row, filtered_point(row));
    }
    pending_.clear();
  }
  commit_all({state_.get(), contacts_.get()});
}

bool CsvLogs::write_failed() const { return (state_ && state_->failed()) || (contacts_ && contacts_->failed()); }

}  // namespace gearsim::sim
