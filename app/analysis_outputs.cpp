#include "app/analysis_outputs.hpp"

#include <fstream>
#include <iomanip>

#include "core/errors.hpp"

namespace gearsim::app {
namespace {

using json = nlohmann::ordered_json;

std::ofstream open_csv(const std::filesystem::path& path) {
  std::ofstream f(path);
  if (!f) throw InputError(path.string() + ": cannot write");
  f << std::setprecision(10);
  return f;
}

}  // namespace

void write_spectrum_csv(const std::filesystem::path& path, const std::vector<std::pair<std::string, Spectrum>>& spectra,
                        double top_hz) {
  std::ofstream f = open_csv(path);
  f << "frequency_hz";
  for (const auto& [pair, s] : spectra) f << ',' << pair << "_amplitude_N";
  f << '\n';
  if (spectra.empty()) return;
  const Spectrum& first = spectra.front().second;
  for (std::size_t k = 0; k < first.frequency_hz.size() && first.frequency_hz[k] <= top_hz; ++k) {
    f << first.frequency_hz[k];
    for (const auto& [pair, s] : spectra) f << ',' << s.amplitude.at(k);
    f << '\n';
  }
}

void write_sidebands_csv(const std::filesystem::path& path, const json& a) {
  std::ofstream f = open_csv(path);
  f << "pair,harmonic_order,around_hz,offset_hz,frequency_hz,amplitude_N,amplitude_db_re_harmonic,over_floor_db,matched\n";
  for (const auto& [pair, p] : a["pairs"].items())
    for (const auto& h : p["mesh_harmonics"]) {
      if (!h.contains("peak_hz")) continue;
      for (const auto& b : h["sidebands"])
        f << pair << ',' << h["order"].get<int>() << ',' << h["peak_hz"].get<double>() << ',' << b["offset_hz"].get<double>()
          << ',' << b["frequency_hz"].get<double>() << ',' << b["amplitude_N"].get<double>() << ','
          << b["level_db_re_harmonic"].get<double>() << ',' << b["over_floor_db"].get<double>() << ','
          << (b.contains("match") ? b["match"].get<std::string>() : "") << '\n';
    }
}

void write_teeth_csv(const std::filesystem::path& path, const json& a) {
  std::ofstream f = open_csv(path);
  f << "pair,gear,tooth,mean_force_N,z_score,flagged\n";
  if (!a.contains("tooth_loads")) return;
  for (const auto& t : a["tooth_loads"])
    for (const auto& tooth : t["teeth"]) {
      const int k = tooth["tooth"].get<int>();
      bool flagged = false;
      for (int g : t["flagged_teeth"]) flagged = flagged || g == k;
      f << t["pair"].get<std::string>() << ',' << t["gear"].get<std::string>() << ',' << k << ','
        << tooth["mean_force_N"].get<double>() << ',';
      if (tooth["z_score"].is_number()) f << tooth["z_score"].get<double>();
      f << ',' << (flagged ? 1 : 0) << '\n';
    }
}

void add_to_summary(json& summary, const json& a) {
  summary["mesh_frequency_hz"] = a["gear_train"]["mesh_hz"];
  json peaks = json::object(), sidebands = json::array(), faulty = json::array();
  for (const auto& [pair, p] : a["pairs"].items()) {
    json list = json::array();
    for (const auto& h : p["mesh_harmonics"]) {
      list.push_back(h.contains("peak_hz") ? h["peak_hz"] : json());
      if (!h.contains("peak_hz")) continue;
      for (const auto& b : h["sidebands"])
        sidebands.push_back({{"pair", pair},
                             {"around_hz", h["peak_hz"]},
                             {"offset_hz", b["offset_hz"]},
                             {"amplitude_db", b["level_db_re_harmonic"]},
                             {"matched", b.contains("match") ? b["match"] : json()}});
    }
    peaks[pair] = list;
  }
  summary["peaks_hz"] = peaks;
  summary["sidebands"] = sidebands;
  if (a.contains("transmission_error")) {
    const json& te = a["transmission_error"];
    summary["te"] = {{"min_rad", te["min_rad"]}, {"max_rad", te["max_rad"]}, {"p2p_rad", te["peak_to_peak_rad"]},
                     {"rms_rad", te["rms_rad"]}};
  }
  if (a.contains("tooth_loads"))
    for (const auto& t : a["tooth_loads"])
      for (int k : t["flagged_teeth"])
        faulty.push_back({{"pair", t["pair"]}, {"gear", t["gear"]}, {"tooth", k},
                          {"z_score", t["teeth"][static_cast<std::size_t>(k)]["z_score"]},
                          {"mean_force_N", t["teeth"][static_cast<std::size_t>(k)]["mean_force_N"]},
                          {"z_threshold", t["z_threshold"]}, {"min_relative_deviation", t["min_relative_deviation"]}});
  summary["faulty_teeth"] = faulty;
}

}  // namespace gearsim::app
