#include "sim/csv_logs.hpp"

#include <algorithm>
#include <iomanip>

#include "core/errors.hpp"
#include "sim/simulate.hpp"

namespace gearsim::sim {
namespace {

std::ofstream open_log(const std::filesystem::path& p) {
  std::ofstream f(p);
  if (!f) throw InputError(p.string() + ": cannot write");
  f << std::setprecision(17);
  return f;
}

}  // namespace

CsvLogs::CsvLogs(const std::filesystem::path& dir, const physics::Scenario& scenario)
    : dir_(dir), scenario_(scenario) {
  if (scenario.transmission) {
    te_in_ = body_of_joint(scenario, scenario.transmission->input_joint);
    te_out_ = body_of_joint(scenario, scenario.transmission->output_joint);
  }
}

void CsvLogs::on_start(const physics::World& world) {
  state_ = open_log(dir_ / "state.csv");
  contacts_ = open_log(dir_ / "contacts.csv");
  state_ << "time_s";
  for (const physics::BodyState& b : world.bodies()) state_ << ',' << b.name << "_angle_rad," << b.name << "_speed_rad_s";
  if (scenario_.transmission) state_ << ",te_rad";
  state_ << '\n';
  contacts_ << "time_s";
  for (const physics::GearPairInfo& p : world.gear_pairs()) {
    const std::string n = p.body_a + "__" + p.body_b;
    contacts_ << ',' << n << "_force_N," << n << "_tooth_pairs," << n << "_max_depth_um";
  }
  contacts_ << '\n';
}

void CsvLogs::on_sample(const physics::World& world) {
  state_ << world.time_s();
  for (const physics::BodyState& b : world.bodies()) state_ << ',' << b.angle_rad << ',' << b.speed_rad_s;
  if (scenario_.transmission)
    state_ << ',' << world.bodies()[te_in_].angle_rad - scenario_.transmission->ratio * world.bodies()[te_out_].angle_rad;
  state_ << '\n';
  contacts_ << world.time_s();
  for (std::size_t p = 0; p < world.gear_pairs().size(); ++p) {
    double force = 0, depth = 0;
    int n = 0;
    for (const physics::ContactSample& c : world.contacts())
      if (c.pair == static_cast<int>(p)) force += c.normal_force_N, depth = std::max(depth, c.geometry.depth_m), ++n;
    contacts_ << ',' << force << ',' << n << ',' << depth * 1e6;
  }
  contacts_ << '\n';
}

void CsvLogs::on_stop(const physics::World&) {
  state_.flush();
  contacts_.flush();
}

}  // namespace gearsim::sim
