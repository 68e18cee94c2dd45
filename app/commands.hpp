// The subcommands of the gearsim CLI. Each registers itself on the CLI11 app and runs when chosen.
// Subcommands print through app/log.hpp only.
#pragma once

#include <CLI/CLI.hpp>

namespace gearsim::app {

void register_tolerance(CLI::App& app);
void register_gears(CLI::App& app);
void register_inspect(CLI::App& app);
void register_run(CLI::App& app);
void register_analyze(CLI::App& app);
void register_report(CLI::App& app);
void register_render(CLI::App& app);
void register_fe_te(CLI::App& app);
void register_modes(CLI::App& app);
void register_sweep(CLI::App& app);

}  // namespace gearsim::app
