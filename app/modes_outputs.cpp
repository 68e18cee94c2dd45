#include "app/modes_outputs.hpp"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "app/html.hpp"
#include "core/errors.hpp"
#include "core/output_file.hpp"

namespace gearsim::app {
namespace {

using Json = nlohmann::json;

Json shape_json(const linear::LumpedModel& m, const Eigen::VectorXd& phi) {
  Json j = Json::object();
  for (const linear::BodyInfo& b : m.bodies)
    if (b.first_dof >= 0) j[b.name] = {{"x_m", phi(b.first_dof)}, {"y_m", phi(b.first_dof + 1)}, {"theta_rad", phi(b.first_dof + 2)}};
  return j;
}

const char* kind_name(linear::Element::Kind k) {
  switch (k) {
    case linear::Element::Kind::Mesh:
      return "mesh";
    case linear::Element::Kind::Bearing:
      return "bearing";
    case linear::Element::Kind::Torsion:
      return "torsion";
  }
  return "";
}

}  // namespace

nlohmann::json modes_json(const std::string& scenario, const linear::LumpedModel& m, const linear::ModalAnalysis& a,
                          const linear::Campbell& c) {
  Json j;
  j["scenario"] = scenario;
  j["drive"] = m.drive;
  j["coordinates"] = m.dofs();
  j["free_coordinates"] = a.free_coordinates;
  j["constraints"] = m.constraint_names;
  Json freqs = Json::array();
  for (const linear::Mode& md : a.modes) freqs.push_back(md.frequency_hz);
  j["natural_frequencies_hz"] = freqs;
  Json groups = Json::array();
  for (const linear::ModeGroup& g : a.groups) {
    Json gj = {{"frequency_hz", g.frequency_hz}, {"multiplicity", g.multiplicity}, {"type", linear::to_string(g.type)}};
    const linear::Mode& first = a.modes[static_cast<std::size_t>(g.modes.front())];
    if (g.type == linear::ModeType::Rotational) gj["planets_alike"] = first.planets_alike;
    if (!first.energy_share.empty()) {
      // The group's strain energy shares, averaged over its members (each member's depends on
      // which basis of the repeated frequency's space the solver returned; the mean does not).
      Json shares = Json::object();
      for (std::size_t e = 0; e < m.elements.size(); ++e) {
        double s = 0;
        for (int k : g.modes) s += a.modes[static_cast<std::size_t>(k)].energy_share[e];
        shares[std::string(kind_name(m.elements[e].kind)) + " " + m.elements[e].name] = s / g.multiplicity;
      }
      gj["strain_energy_share"] = shares;
    }
    Json shapes = Json::array();
    for (int k : g.modes) shapes.push_back(shape_json(m, a.modes[static_cast<std::size_t>(k)].shape));
    gj["shapes"] = shapes;
    groups.push_back(gj);
  }
  j["modes"] = groups;
  Json meshes = Json::array();
  for (const linear::MeshInfo& mi : m.meshes)
    meshes.push_back({{"gears", {m.bodies[mi.a].name, m.bodies[mi.b].name}},
                      {"driven", m.bodies[mi.driven].name},
                      {"mean_stiffness_N_per_m", mi.mean_N_per_m},
                      {"min_stiffness_N_per_m", mi.min_N_per_m},
                      {"max_stiffness_N_per_m", mi.max_N_per_m},
                      {"mean_tooth_pairs", mi.mean_pairs},
                      {"line_of_action_deg", mi.line_of_action_deg}});
  j["meshes"] = meshes;
  Json supports = Json::array();
  for (const linear::Element& e : m.elements)
    if (e.kind != linear::Element::Kind::Mesh)
      supports.push_back(
          {{"body", e.name},
           {"kind", kind_name(e.kind)},
           {e.kind == linear::Element::Kind::Bearing ? "radial_stiffness_N_per_m" : "torsional_stiffness_N_m_per_rad", e.value}});
  j["supports"] = supports;
  Json cj;
  cj["drive"] = c.drive;
  if (!c.why_not.empty()) cj["unavailable"] = c.why_not;
  if (c.operating_speed_rad_s) cj["operating_speed_rad_s"] = *c.operating_speed_rad_s;
  Json rates = Json::array();
  for (const linear::MeshRate& r : c.rates)
    rates.push_back(
        {{"gears", {m.bodies[m.meshes[r.mesh].a].name, m.bodies[m.meshes[r.mesh].b].name}}, {"mesh_hz_per_rad_s", r.hz_per_rad_s}});
  cj["mesh_rates"] = rates;
  Json cross = Json::array();
  for (const linear::Crossing& x : c.crossings)
    cross.push_back({{"natural_frequency_hz", x.natural_frequency_hz},
                     {"mode", x.group},
                     {"harmonic", x.harmonic},
                     {"gears", {m.bodies[m.meshes[x.mesh].a].name, m.bodies[m.meshes[x.mesh].b].name}},
                     {"drive_speed_rad_s", x.drive_speed_rad_s},
                     {"mesh_frequency_hz", x.natural_frequency_hz / x.harmonic}});
  cj["crossings"] = cross;
  j["campbell"] = cj;
  return j;
}

void write_mode_shapes_csv(const std::filesystem::path& file, const linear::LumpedModel& m, const linear::ModalAnalysis& a) {
  OutputFile out(file);
  out << std::setprecision(10) << "mode,frequency_hz,body,x_m,y_m,theta_rad\n";
  for (std::size_t i = 0; i < a.modes.size(); ++i)
    for (const linear::BodyInfo& b : m.bodies)
      if (b.first_dof >= 0) {
        const Eigen::VectorXd& p = a.modes[i].shape;
        out << i << ',' << a.modes[i].frequency_hz << ',' << b.name << ',' << p(b.first_dof) << ',' << p(b.first_dof + 1) << ','
            << p(b.first_dof + 2) << '\n';
      }
  out.commit();
}

void write_campbell_csv(const std::filesystem::path& file, const linear::LumpedModel& m, const linear::Campbell& c) {
  OutputFile out(file);
  out << std::setprecision(10) << "mode,natural_frequency_hz,harmonic,gear_a,gear_b,mesh_frequency_hz,drive_speed_rad_s,drive_speed_rpm\n";
  for (const linear::Crossing& x : c.crossings)
    out << x.group << ',' << x.natural_frequency_hz << ',' << x.harmonic << ',' << m.bodies[m.meshes[x.mesh].a].name << ','
        << m.bodies[m.meshes[x.mesh].b].name << ',' << x.natural_frequency_hz / x.harmonic << ',' << x.drive_speed_rad_s << ','
        << x.drive_speed_rad_s * 60 / (2 * M_PI) << '\n';
  out.commit();
}

void write_modes_svg(const std::filesystem::path& file, const linear::LumpedModel& m, const linear::ModalAnalysis& a, int groups) {
  // The picture's extent: every body's rim.
  double extent = 1e-3;
  for (const linear::BodyInfo& b : m.bodies) extent = std::max(extent, b.centre_of_mass_m.norm() + std::max(b.radius_m, 1e-3));
  std::vector<int> shown;
  for (std::size_t g = 0; g < a.groups.size() && static_cast<int>(shown.size()) < groups; ++g)
    if (a.groups[g].frequency_hz > 0) shown.push_back(static_cast<int>(g));
  const int panel = 320, cols = 3, rows = static_cast<int>((shown.size() + cols - 1) / cols);
  std::ostringstream svg;
  svg << std::setprecision(6) << "<svg xmlns='http://www.w3.org/2000/svg' width='" << panel * cols << "' height='"
      << panel * std::max(rows, 1) << "' font-family='sans-serif' font-size='12'>\n";
  const double px_per_m = 0.42 * panel / extent;
  for (std::size_t s = 0; s < shown.size(); ++s) {
    const linear::ModeGroup& g = a.groups[static_cast<std::size_t>(shown[s])];
    const Eigen::VectorXd& phi = a.modes[static_cast<std::size_t>(g.modes.front())].shape;
    // Scale: the largest rim motion |u| + r|θ| drawn as 8 % of the panel.
    double largest = 0;
    for (const linear::BodyInfo& b : m.bodies)
      if (b.first_dof >= 0)
        largest = std::max(largest, phi.segment<2>(b.first_dof).norm() + std::max(b.radius_m, 1e-3) * std::abs(phi(b.first_dof + 2)));
    const double k = largest > 0 ? 0.08 * panel / px_per_m / largest : 0;
    const int col = static_cast<int>(s) % cols, row = static_cast<int>(s) / cols;
    const double ox = col * panel + panel / 2.0, oy = row * panel + panel / 2.0 + 10;
    svg << "<text x='" << col * panel + 8 << "' y='" << row * panel + 16 << "'>" << num(g.frequency_hz, 5) << " Hz ×" << g.multiplicity
        << " " << linear::to_string(g.type) << "</text>\n";
    for (const linear::BodyInfo& b : m.bodies) {
      const double r = std::max(b.radius_m, 2e-3) * px_per_m;
      const double x0 = ox + b.centre_of_mass_m.x() * px_per_m, y0 = oy - b.centre_of_mass_m.y() * px_per_m;
      const char* dash = b.gear ? "" : " stroke-dasharray='4 3'";
      svg << "<circle cx='" << x0 << "' cy='" << y0 << "' r='" << r << "' fill='none' stroke='#ccc'" << dash << "><title>"
          << html_escape(b.name) << "</title></circle>\n";
      if (b.first_dof < 0) continue;
      const double x = x0 + k * phi(b.first_dof) * px_per_m, y = y0 - k * phi(b.first_dof + 1) * px_per_m;
      const double t = k * phi(b.first_dof + 2);
      svg << "<circle cx='" << x << "' cy='" << y << "' r='" << r << "' fill='none' stroke='#c33'" << dash << "/>\n"
          << "<line x1='" << x << "' y1='" << y << "' x2='" << x + r * std::cos(t) << "' y2='" << y - r * std::sin(t)
          << "' stroke='#c33'/>\n";
    }
  }
  svg << "</svg>\n";
  write_output_file(file, svg.str());
}

}  // namespace gearsim::app
