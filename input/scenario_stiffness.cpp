// contact.stiffness_tables: each entry's two gear names resolved to the meshing body pairs they
// match, its CSV file read and checked, and its range checked against each pair's active flank
// on the first gear. See parse_stiffness_tables() in scenario_parts.hpp.
#include <cmath>
#include <algorithm>
#include <map>
#include <sstream>
#include <tuple>

#include "input/csv_table.hpp"
#include "input/scenario_parts.hpp"
#include "core/errors.hpp"
#include "geometry/gear_dimensions.hpp"
#include "geometry/gear_mesh.hpp"

namespace gearsim::input::scenario_detail {
namespace {

namespace fs = std::filesystem;

// Slack on the coverage check, m: a table written to 0.1 µm (or read back through decimal text)
// still covers an active flank it was made for.
constexpr double kCoverageSlack_m = 1e-9;

// `name` names the body itself, or the family the planetary macro numbers: "planet" matches
// planet_0, planet_1, ...
bool matches(const std::string& name, const std::string& body) {
  if (body == name) return true;
  if (body.size() <= name.size() + 1 || body.compare(0, name.size(), name) != 0 || body[name.size()] != '_') return false;
  for (std::size_t i = name.size() + 1; i < body.size(); ++i)
    if (body[i] < '0' || body[i] > '9') return false;
  return true;
}

bool toothed(const physics::BodyDef& b) { return b.gear || (b.mesh && b.mesh->teeth); }

// Can two generated gears at their poses reach each other (as the world decides, from tip radii)?
bool can_reach(const GearSpec& a, const GearSpec& b, double d) {
  const bool ia = a.kind == GearKind::Internal, ib = b.kind == GearKind::Internal;
  if (ia && ib) return false;
  const double ra = gear_dimensions(a).tip_radius_m, rb = gear_dimensions(b).tip_radius_m;
  if (!ia && !ib) return d < ra + rb;
  return d + (ia ? rb : ra) > (ia ? ra : rb);
}

// Radii on gear a from its start of active profile to its tip, m (low, high).
std::pair<double, double> active_flank(const GearSpec& a, const GearSpec& b, double d) {
  const bool a_internal = a.kind == GearKind::Internal;
  const MeshGeometry g = a_internal ? analyse_mesh(b, a, d) : analyse_mesh(a, b, d);
  const GearDimensions da = gear_dimensions(a);
  const double roll = std::max(0.0, a_internal ? g.active_start_roll_b_m : g.active_start_roll_a_m);
  const double start = std::hypot(da.base_radius_m, roll);
  return {std::min(start, da.tip_radius_m), std::max(start, da.tip_radius_m)};
}

// Refuses (naming `gears`) an entry whose names match no gear body.
void require_gear_names(const YamlMap& m, const std::vector<std::string>& names, const physics::Scenario& s) {
  for (const std::string& name : names) {
    bool any = false;
    for (const physics::BodyDef& b : s.bodies) any = any || (toothed(b) && matches(name, b.name));
    if (!any) m.fail("gears", "no gear body named '" + name + "' (or '" + name + "_<n>')");
  }
}

// The body pairs an entry's `gears: [A, B]` names that can mesh (A's body first, its centre
// distance d); refused naming `gears` when a name matches no gear body or no pair meshes.
struct NamedPair {
  const physics::BodyDef* a;
  const physics::BodyDef* b;
  double distance_m;
};
std::vector<NamedPair> meshing_pairs(const YamlMap& m, const std::vector<std::string>& names, const physics::Scenario& s) {
  require_gear_names(m, names, s);
  std::vector<NamedPair> out;
  for (const physics::BodyDef& a : s.bodies)
    for (const physics::BodyDef& b : s.bodies) {
      if (&a == &b || !toothed(a) || !toothed(b) || !matches(names[0], a.name) || !matches(names[1], b.name)) continue;
      const double d = (a.pose.position_m - b.pose.position_m).head<2>().norm();
      if (a.gear && b.gear && !can_reach(*a.gear, *b.gear, d)) continue;
      out.push_back({&a, &b, d});
    }
  if (out.empty()) m.fail("gears", "gears '" + names[0] + "' and '" + names[1] + "' do not mesh anywhere in this scenario");
  return out;
}

contact::StiffnessTable read_table(const YamlMap& m, const fs::path& dir) {
  contact::StiffnessTable t;
  const fs::path file = resolve(dir, m.string("file"));
  if (std::error_code ec; !fs::is_regular_file(file, ec)) m.fail("file", "stiffness table not found: " + file.string());
  t.source = file.string();
  try {
    const CsvTable csv = read_csv(file);
    t.radius_m = csv.column("radius_a_m");
    t.stiffness_N_per_m_per_m = csv.column("stiffness_N_per_m_per_m");
  } catch (const InputError& e) {
    m.fail("file", std::string(e.what()) + " (expected columns radius_a_m,stiffness_N_per_m_per_m)");
  }
  if (const Check c = contact::check_stiffness_table(t); !c) {
    std::ostringstream where;  // the CSV line: its header is line 1, row 0 is line 2
    where << t.source;
    if (c.refusal().index >= 0) where << ':' << c.refusal().index + 2;
    m.fail("file", where.str() + ": " + c.reason());
  }
  return t;
}

std::string mm(double r_m) {
  std::ostringstream s;
  s.precision(7);
  s << r_m * 1e3;
  return s.str();
}

}  // namespace

void parse_stiffness_tables(const std::vector<YamlMap>& entries, physics::Scenario& s, const fs::path& dir) {
  std::map<std::pair<std::string, std::string>, std::string> taken;  // body pair → its table
  // Active flanks by (gear a, gear b, centre distance in nm): a planetary set's planets share one.
  std::map<std::tuple<std::string, std::string, long long>, std::pair<double, double>> flanks;
  for (const YamlMap& m : entries) {
    const std::vector<std::string> names = m.strings("gears", 2);
    const contact::StiffnessTable table = read_table(m, dir);
    double body = 0;
    if (given(m, "body_stiffness_N_per_m")) {
      body = m.number("body_stiffness_N_per_m");
      if (!within(body, limits::kStiffness_N_per_m))
        m.fail("body_stiffness_N_per_m", limit_message(limits::kStiffness_N_per_m, body) + " (omit the key for rigid gear bodies)");
    }
    m.reject_unknown_keys();
    for (const auto& [pa, pb, d] : meshing_pairs(m, names, s)) {
      const physics::BodyDef &a = *pa, &b = *pb;
      const bool generated = a.gear && b.gear;
      const auto key = a.name < b.name ? std::make_pair(a.name, b.name) : std::make_pair(b.name, a.name);
      if (const auto [it, fresh] = taken.emplace(key, table.source); !fresh)
        m.fail("gears", "gears '" + a.name + "' and '" + b.name + "' already have a stiffness table (" + it->second + ")");
      if (generated) {
        // The table must span the active flank on a (contacts outside it are counted in the run).
        const auto at = std::make_tuple(a.gear->name, b.gear->name, std::llround(d * 1e9));
        if (!flanks.count(at)) try {
            flanks[at] = active_flank(*a.gear, *b.gear, d);
          } catch (const InputError& e) {
            m.fail("gears", "'" + a.name + "' and '" + b.name + "': " + e.what());
          }
        const std::pair<double, double> flank = flanks.at(at);
        if (table.radius_m.front() > flank.first + kCoverageSlack_m || table.radius_m.back() < flank.second - kCoverageSlack_m)
          m.fail("file", table.source + " covers radii " + mm(table.radius_m.front()) + "–" + mm(table.radius_m.back()) + " mm on '" +
                             a.name + "', but its active flank meshing '" + b.name + "' spans " + mm(flank.first) + "–" + mm(flank.second) +
                             " mm (start of active profile to tip)");
      }
      s.contact.stiffness_tables.push_back({a.name, b.name, table, body});
    }
  }
}

void parse_mesh_stiffnesses(const std::vector<YamlMap>& entries, physics::Scenario& s) {
  std::map<std::pair<std::string, std::string>, std::string> taken;  // body pair → what set its stiffness
  for (const physics::PairStiffnessDef& t : s.contact.stiffness_tables)
    taken[std::minmax(t.body_a, t.body_b)] = "a stiffness table (" + t.table.source + ")";
  for (const YamlMap& m : entries) {
    const std::vector<std::string> names = m.strings("gears", 2);
    const double k = number_within(m, "stiffness_N_per_m", limits::kStiffness_N_per_m);
    m.reject_unknown_keys();
    for (const auto& [a, b, d] : meshing_pairs(m, names, s)) {
      if (const auto [it, fresh] = taken.emplace(std::minmax(a->name, b->name), "a mesh stiffness"); !fresh)
        m.fail("gears", "gears '" + a->name + "' and '" + b->name + "' already have " + it->second);
      s.contact.mesh_stiffnesses.push_back({a->name, b->name, k});
    }
  }
}

}  // namespace gearsim::input::scenario_detail
