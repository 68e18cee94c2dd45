// gearsim analyze DIR: the analysis of a finished run (app/run_analysis.hpp), written to
// DIR/analysis.json and DIR/spectrum_<pair>.csv, with a short summary on stdout.
#include <iomanip>
#include <iostream>

#include "app/analyze.hpp"
#include "app/commands.hpp"
#include "app/output_folder.hpp"
#include "input/input_limits.hpp"
#include "app/run_analysis.hpp"
#include "app/run_dir.hpp"

namespace gearsim::app {

void print_analysis(const nlohmann::ordered_json& j, std::ostream& out) {
  out << std::fixed << std::setprecision(2);
  out << "analysis of " << j["scenario"].get<std::string>() << ", " << j["window_s"][0].get<double>() << "–"
      << j["window_s"][1].get<double>() << " s; mesh frequency " << j["gear_train"]["mesh_hz"].get<double>() << " Hz";
  const auto& train = j["gear_train"];
  if (train.contains("stages")) {
    out << " (the first stage's); overall ratio " << std::setprecision(6) << train["ratio"].get<double>() << "\n";
    for (const auto& st : train["stages"]) {
      out << "  stage " << st["name"].get<std::string>() << ", " << st["kind"].get<std::string>() << " " << st["input"].get<std::string>()
          << " → " << st["output"].get<std::string>() << ": ratio " << std::setprecision(6) << st["ratio"].get<double>()
          << ", mesh frequency " << std::setprecision(2) << st["mesh_hz"].get<double>() << " Hz";
      if (st.contains("transmission_error"))
        out << ", TE peak-to-peak " << std::scientific << std::setprecision(3) << st["transmission_error"]["peak_to_peak_rad"].get<double>()
            << " rad" << std::fixed;
      out << std::setprecision(2) << "\n";
    }
  } else {
    out << "\n";
  }
  for (const auto& [pair, p] : j["pairs"].items()) {
    out << "  " << pair << ": mean " << p["mean_force_N"].get<double>() << " N, zero-force samples "
        << 100 * p["zero_force_share"].get<double>() << " %";
    if (p.contains("steps_without_force_share"))
      out << ", steps without force " << 100 * p["steps_without_force_share"].get<double>() << " %";
    out << std::setprecision(3) << ", dynamic factor " << p["dynamic_factor_band_limited"].get<double>() << " band-limited";
    if (p.contains("dynamic_factor_per_step")) out << ", " << p["dynamic_factor_per_step"].get<double>() << " per step";
    out << std::setprecision(2);
    out << "; harmonics";
    for (const auto& h : p["mesh_harmonics"])
      if (h.contains("peak_hz"))
        out << " " << h["peak_hz"].get<double>() << " Hz (+" << h["over_median_floor_0_1000_hz_db"].get<double>() << " dB)";
    out << "\n";
  }
  if (j.contains("contact_loss")) {
    out << "  note: in";
    for (const auto& p : j["contact_loss"]["pairs"]) out << " " << p.get<std::string>();
    out << ", " << j["contact_loss"]["note"].get<std::string>() << "\n";
  }
  if (j.contains("transmission_error"))
    out << "  transmission error: peak-to-peak " << std::scientific << std::setprecision(3)
        << j["transmission_error"]["peak_to_peak_rad"].get<double>() << " rad\n"
        << std::fixed << std::setprecision(2);
  if (j.contains("tooth_loads"))
    for (const auto& t : j["tooth_loads"]) {
      if (t["flagged_teeth"].empty()) continue;
      out << "  " << t["pair"].get<std::string>() << ": " << t["gear"].get<std::string>() << " teeth standing out:";
      for (int k : t["flagged_teeth"])
        out << " " << k << " (" << t["teeth"][static_cast<std::size_t>(k)]["mean_force_N"].get<double>() << " N, z "
            << t["teeth"][static_cast<std::size_t>(k)]["z_score"].get<double>() << ")";
      out << "\n";
    }
}

void register_analyze(CLI::App& app) {
  auto dir = std::make_shared<std::string>();
  auto from = std::make_shared<double>(-1);
  CLI::App* sub = app.add_subcommand("analyze",
                                     "Analyse a run folder: force spectra, mesh harmonics, sidebands, "
                                     "fault-frequency family, transmission error, per-tooth loads.");
  sub->add_option("dir", *dir, "A folder written by `gearsim run --out`.")->required()->check(CLI::ExistingDirectory);
  sub->add_option("--from", *from, "Start of the analysed window, s (default: the end of the motors' ramp).")
      ->check(input::cli_within(input::limits::kRunTime_s));
  sub->callback([dir, from] {
    const OutputFolder folder(*dir, "gearsim analyze");
    const RunDir run = open_run_dir(*dir);
    print_analysis(write_run_analysis(run, {*from}), std::cout);
    std::cout << "written: " << (run.dir / "analysis.json").string() << "\n";
  });
}

}  // namespace gearsim::app
