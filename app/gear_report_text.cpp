// Text rendering of the gear-set analysis document (see gear_report.hpp).
#include <cmath>

#include "app/gear_report.hpp"

namespace gearsim::app {
namespace {

std::string mm(const json& v, int digits = 4) { return fixed(v.get<double>() * 1e3, digits); }

void row(std::ostream& out, const std::string& label, const std::vector<std::string>& cells) {
  out << "  " << pad(label, 34);
  for (const std::string& c : cells) out << pad(c, 15, true);
  out << "\n";
}

void print_gear_table(std::ostream& out, const json& gears) {
  std::vector<std::string> names;
  for (const auto& [name, g] : gears.items()) names.push_back(name);
  auto cells = [&](auto f) {
    std::vector<std::string> c;
    for (const std::string& n : names) c.push_back(f(gears[n]));
    return c;
  };
  out << "Gear table, from first principles (lengths in mm):\n";
  row(out, "", names);
  row(out, "kind", cells([](const json& g) { return g["kind"].get<std::string>(); }));
  row(out, "teeth z", cells([](const json& g) { return std::to_string(g["teeth"].get<int>()); }));
  bool helical = false;
  for (const std::string& n : names) helical = helical || gears[n].contains("helix_angle_deg");
  if (helical) {
    // Helical gears: the normal values they were given, the helix, and the transverse section's.
    const auto or_dash = [](const json& g, const char* key, auto show) { return g.contains(key) ? show(g[key]) : std::string("-"); };
    row(out, "helix angle β (°), hand", cells([&](const json& g) {
          return or_dash(g, "helix_angle_deg", [&](const json& v) { return fixed(v, 3) + " " + g["hand"].get<std::string>(); });
        }));
    row(out, "normal module m_n", cells([&](const json& g) { return or_dash(g, "normal_module_m", [](const json& v) { return mm(v); }); }));
    row(out, "normal pressure angle α_n (°)",
        cells([&](const json& g) { return or_dash(g, "normal_pressure_angle_deg", [](const json& v) { return fixed(v, 3); }); }));
    row(out, "base helix angle β_b (°)",
        cells([&](const json& g) { return or_dash(g, "base_helix_angle_deg", [](const json& v) { return fixed(v, 3); }); }));
    row(out, "axial pitch p_x", cells([&](const json& g) { return or_dash(g, "axial_pitch_m", [](const json& v) { return mm(v); }); }));
  }
  row(out, helical ? "transverse module m_t" : "module m", cells([](const json& g) { return mm(g["module_m"]); }));
  row(out, helical ? "transverse pressure angle α_t (°)" : "pressure angle α (°)",
      cells([](const json& g) { return fixed(g["pressure_angle_deg"], 3); }));
  row(out, "face width b", cells([](const json& g) { return mm(g["face_width_m"], 3); }));
  row(out, helical ? "transverse profile shift x_t" : "profile shift x", cells([](const json& g) { return fixed(g["profile_shift"], 3); }));
  row(out, "reference diameter d = m·z", cells([](const json& g) { return mm(g["reference_diameter_m"]); }));
  row(out, "base diameter d_b = d·cos α", cells([](const json& g) { return mm(g["base_diameter_m"]); }));
  row(out, "tip diameter d_a", cells([](const json& g) { return mm(g["tip_diameter_m"]); }));
  row(out, "root diameter d_f", cells([](const json& g) { return mm(g["root_diameter_m"]); }));
  row(out, "form diameter d_Ff (involute start)", cells([](const json& g) { return mm(g["form_diameter_m"]); }));
  row(out, "tooth thickness s (reference, arc)", cells([](const json& g) { return mm(g["tooth_thickness_m"]); }));
  row(out, "tip land s_a (arc)", cells([](const json& g) { return mm(g["tip_thickness_m"]); }));
  row(out, "span W_k (k)", cells([](const json& g) {
        return g.contains("span_m") ? mm(g["span_m"]) + " (" + std::to_string(g["span_teeth"].get<int>()) + ")" : std::string("-");
      }));
  row(out, "flank / pitch / slope errors", cells([](const json& g) {
        const json& e = g["errors"];
        return std::to_string(e["flank_offsets"].get<int>()) + "/" + std::to_string(e["pitch_errors"].get<int>()) + "/" +
               std::to_string(e["profile_slopes"].get<int>());
      }));
  row(out, "mesh triangles", cells([](const json& g) { return std::to_string(g["mesh"]["triangles"].get<int>()); }));
  row(out, "watertight, manifold", cells([](const json& g) {
        return std::string(g["mesh"]["watertight"].get<bool>() ? "yes" : "NO") + ", " + (g["mesh"]["manifold"].get<bool>() ? "yes" : "NO");
      }));
  row(out, "volume (mm³)", cells([](const json& g) { return fixed(g["mesh"]["volume_m3"].get<double>() * 1e9, 2); }));
  row(out, "mass (g)", cells([](const json& g) { return fixed(g["mesh"]["mass_kg"].get<double>() * 1e3, 3); }));
  row(out, "J_zz about the axis (kg·mm²)",
      cells([](const json& g) { return fixed(g["mesh"]["inertia_zz_kg_m2"].get<double>() * 1e6, 4); }));
  row(out, "convex pieces (sectors exact)", cells([](const json& g) {
        const json& d = g["decomposition"];
        return std::to_string(d["pieces"].get<int>()) + (d["sectors_exact"].get<bool>() ? " (yes)" : " (no)");
      }));
  row(out, "union vs mesh, Hausdorff (µm)",
      cells([](const json& g) { return fixed(g["decomposition"]["hausdorff_m"].get<double>() * 1e6, 6); }));
}

void print_mesh(std::ostream& out, const std::string& label, const json& m) {
  out << "  " << label << ": a = " << mm(m["centre_distance_m"], 3) << " mm, α_w = " << fixed(m["working_pressure_angle_deg"], 3)
      << "°, contact ratio ε_α = " << fixed(m["contact_ratio"], 3) << " (" << fixed(m["effective_contact_ratio"], 3)
      << " once cut off at the form circles)";
  if (m.contains("overlap_ratio") && m["overlap_ratio"].get<double>() > 0)
    out << ", overlap ratio ε_β = " << fixed(m["overlap_ratio"], 3) << ", total ε_γ = " << fixed(m["total_contact_ratio"], 3);
  out << "\n";
}

}  // namespace

void print_gearset(std::ostream& out, const json& doc) {
  out << "Gear set '" << doc["name"].get<std::string>() << "' (" << doc["spec_file"].get<std::string>() << "), density "
      << fixed(doc["density_kg_m3"], 0) << " kg/m³\n\n";
  print_gear_table(out, doc["gears"]);
  if (doc.contains("reference")) {
    out << "\nCompared with " << doc["reference"]["source"].get<std::string>() << " (mm):\n";
    for (const json& r : doc["reference"]["rows"])
      out << "  " << pad(r["gear"].get<std::string>(), 8) << pad(r["key"].get<std::string>(), 22) << " published "
          << pad(mm(r["published_m"], 3), 8, true) << "  ours " << pad(mm(r["ours_m"], 3), 8, true) << "  " << r["note"].get<std::string>()
          << "\n";
  }
  if (doc.contains("train")) {
    const json& t = doc["train"];
    out << "\n";
    if (t["type"] == "planetary") {
      out << "Planetary set: sun '" << t["sun"].get<std::string>() << "', " << t["planets"].get<int>() << " × planet '"
          << t["planet"].get<std::string>() << "', ring '" << t["ring"].get<std::string>() << "' (ring fixed, carrier out)\n"
          << "  ratio sun → carrier i = 1 + z_r/z_s = " << fixed(t["ratio_sun_to_carrier"], 4) << "\n"
          << "  assembly (z_s + z_r)/N = " << fixed(t["assembly_quotient"], 4)
          << (t["equally_spaced_assembly"].get<bool>() ? " (integer: equally spaced planets mesh)" : " (NOT an integer)") << "\n"
          << "  clearance between neighbouring planet tips = " << mm(t["adjacency_clearance_m"], 3) << " mm\n";
      print_mesh(out, "sun–planet", t["sun_planet"]);
      print_mesh(out, "planet–ring", t["planet_ring"]);
      out << "  placement: ring turned " << fixed(t["ring_angle_deg"], 4) << "°;";
      for (const json& p : t["placements"])
        out << " planet at " << fixed(p["carrier_angle_deg"], 1) << "° spun " << fixed(p["spin_angle_deg"], 4) << "°;";
      out << "\n";
    } else {
      out << "Gear pair '" << t["driver"].get<std::string>() << "' → '" << t["driven"].get<std::string>() << "', ratio "
          << fixed(t["ratio"], 4) << "\n";
      print_mesh(out, "mesh", t["mesh"]);
    }
    const json& problems = t["type"] == "planetary" ? t["problems"] : t["mesh"]["problems"];
    for (const json& p : problems) out << "  finding: " << p.get<std::string>() << "\n";
  }
  if (doc.contains("tolerance")) {
    out << "\nSingle flank error (paper eqs 1–5) at quality " << doc["tolerance"]["quality"].get<int>() << ", µm:\n";
    out << "  " << pad("gear", 16) << pad("f_f", 8, true) << pad("f_Hα", 8, true) << pad("F_p", 8, true) << pad("F_α", 8, true)
        << pad("F_i'", 8, true) << "   standard, step factor\n";
    for (const auto& [name, g] : doc["tolerance"]["gears"].items())
      for (const char* std_key : {"din3961", "iso1328"}) {
        const json& r = g[std_key];
        out << "  " << pad(name, 16);
        for (const json& c : r["components"]) out << pad(fixed(c["value_um"], 1), 8, true);
        out << "   " << r["standard_name"].get<std::string>() << ", ×" << fixed(r["step_factor"], 4) << "\n";
      }
  }
}

}  // namespace gearsim::app
