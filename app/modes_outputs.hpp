// `gearsim modes` outputs: the modal analysis as JSON (modes.json, --json), mode shapes as CSV,
// the Campbell table as CSV, and an SVG picture of the lowest mode shapes.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "linear/campbell.hpp"
#include "linear/lumped_model.hpp"
#include "linear/modes.hpp"

namespace gearsim::app {

nlohmann::json modes_json(const std::string& scenario, const linear::LumpedModel& model, const linear::ModalAnalysis& modes,
                          const linear::Campbell& campbell);
void write_mode_shapes_csv(const std::filesystem::path& file, const linear::LumpedModel& model, const linear::ModalAnalysis& modes);
void write_campbell_csv(const std::filesystem::path& file, const linear::LumpedModel& model, const linear::Campbell& campbell);
// The first shape of each of the lowest `groups` elastic natural frequencies, deflected bodies
// over their rest outlines.
void write_modes_svg(const std::filesystem::path& file, const linear::LumpedModel& model, const linear::ModalAnalysis& modes, int groups);

}  // namespace gearsim::app
