#include "app/analysis_outputs.hpp"

#include <algorithm>
#include <fstream>
#include <iomanip>

#include "app/analysis_json.hpp"
#include "core/errors.hpp"
#include "core/output_file.hpp"

namespace gearsim::app {
namespace {

using json = nlohmann::ordered_json;

bool contains(const std::vector<int>& list, int k) { return std::find(list.begin(), list.end(), k) != list.end(); }

// The summary's faulty_teeth: every flagged tooth of the step-log tooth loads.
json faulty_teeth(const RunAnalysis& a) {
  json faulty = json::array();
  if (!a.tooth_loads) return faulty;
  for (const ToothLoads& t : *a.tooth_loads)
    for (int k : t.flagged)
      faulty.push_back({{"pair", pair_name(t.pair)},
                        {"gear", t.gear},
                        {"tooth", k},
                        {"z_score", t.z_score.at(static_cast<std::size_t>(k))},
                        {"mean_force_N", t.mean_force_N.at(static_cast<std::size_t>(k))},
                        {"z_threshold", t.z_threshold},
                        {"min_relative_deviation", t.min_relative_deviation}});
  return faulty;
}

}  // namespace

void write_spectrum_csv(const std::filesystem::path& path, const RunAnalysis& a, double top_hz) {
  write_output(path, [&](std::ostream& f) {
    f << std::setprecision(10);
    f << "frequency_hz";
    for (const PairForceAnalysis& p : a.pairs) f << ',' << pair_name(p.pair) << "_amplitude_N";
    f << '\n';
    if (a.pairs.empty()) return;
    const Spectrum& first = a.pairs.front().spectrum;
    for (std::size_t k = 0; k < first.frequency_hz.size() && first.frequency_hz[k] <= top_hz; ++k) {
      f << first.frequency_hz[k];
      for (const PairForceAnalysis& p : a.pairs) f << ',' << p.spectrum.amplitude.at(k);
      f << '\n';
    }
  });
}

void write_sidebands_csv(const std::filesystem::path& path, const RunAnalysis& a) {
  write_output(path, [&](std::ostream& f) {
    f << std::setprecision(10);
    f << "pair,harmonic_order,around_hz,offset_hz,frequency_hz,amplitude_N,amplitude_db_re_harmonic,over_floor_db,matched,mesh_line\n";
    for (const PairForceAnalysis& p : a.pairs)
      for (const MeshHarmonic& h : p.mesh.harmonics) {
        if (!h.peak) continue;
        for (const Sideband& b : h.sidebands)
          f << pair_name(p.pair) << ',' << h.order << ',' << h.peak->frequency_hz << ',' << b.offset_hz << ',' << b.peak.frequency_hz << ','
            << b.peak.amplitude << ',' << b.level_db_re_harmonic << ',' << b.height_over_floor_db << ','
            << (b.match ? match_label(*b.match) : "") << ',' << (b.mesh_line ? b.mesh_line->key : "") << '\n';
      }
  });
}

void write_teeth_csv(const std::filesystem::path& path, const RunAnalysis& a) {
  write_output(path, [&](std::ostream& f) {
    f << std::setprecision(10);
    f << "pair,gear,tooth,mean_force_N,z_score,flagged\n";
    if (!a.tooth_loads) return;
    for (const ToothLoads& t : *a.tooth_loads)
      for (std::size_t k = 0; k < t.mean_force_N.size(); ++k)
        f << pair_name(t.pair) << ',' << t.gear << ',' << k << ',' << t.mean_force_N[k] << ',' << t.z_score[k] << ','
          << (contains(t.flagged, static_cast<int>(k)) ? 1 : 0) << '\n';
  });
}

void add_to_summary(json& summary, const RunAnalysis& a, double mesh_hz) {
  summary["mesh_frequency_hz"] = mesh_hz;
  // Per pair the harmonics' peaks (null where none was found), and every sideband of those found.
  json peaks = json::object(), sidebands = json::array();
  for (const PairForceAnalysis& p : a.pairs) {
    json list = json::array();
    for (const MeshHarmonic& h : p.mesh.harmonics) {
      list.push_back(h.peak ? json(h.peak->frequency_hz) : json());
      if (!h.peak) continue;
      for (const Sideband& b : h.sidebands)
        sidebands.push_back({{"pair", pair_name(p.pair)},
                             {"around_hz", h.peak->frequency_hz},
                             {"offset_hz", b.offset_hz},
                             {"amplitude_db", b.level_db_re_harmonic},
                             {"matched", b.match ? json(match_label(*b.match)) : json()}});
    }
    peaks[pair_name(p.pair)] = list;
  }
  summary["peaks_hz"] = peaks;
  summary["sidebands"] = sidebands;
  if (a.te)
    summary["te"] = {
        {"min_rad", a.te->rad.min}, {"max_rad", a.te->rad.max}, {"p2p_rad", a.te->rad.peak_to_peak}, {"rms_rad", a.te->rad.rms}};
  summary["faulty_teeth"] = faulty_teeth(a);
}

}  // namespace gearsim::app
