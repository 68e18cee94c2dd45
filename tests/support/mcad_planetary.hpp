// Test helper: a planetary scenario of OpenSCAD MCAD meshes (tests/data/mcad: sun z 12, planets
// z 18, ring z 48, module 1, 20°), three planets, the sun driven at 20 rad/s against a carrier
// load; `supports` (YAML text, e.g. "{sun: {radial_stiffness_N_per_m: 1.0e7}}", or "" for rigid
// hinges) put under planetary.supports. Written into `dir`; returns the file.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

namespace gearsim::test {

inline std::filesystem::path mcad_planetary_file(const std::filesystem::path& dir, double carrier_load_N_m,
                                                 const std::string& supports = "") {
  const std::string data = std::string(GEARSIM_SOURCE_DIR) + "/tests/data/mcad/";
  const std::filesystem::path file = dir / "mcad_planetary.yaml";
  std::ofstream(file) << "name: mcad_planetary\nduration_s: 0.03\n"
                         "solver: {time_step_s: 1.0e-5}\n"
                         "output: {sample_rate_hz: 2000, per_step_log: false}\n"
                         "planetary:\n"
                         "  sun: {density_kg_m3: 7850, mesh: {file: "
                      << data
                      << "mcad_m1_z12_a20_f5_b005.stl, unit: mm}}\n"
                         "  planet: {density_kg_m3: 7850, mesh: {file: "
                      << data
                      << "mcad_m1_z18_a20_f5_b005.stl, unit: mm}}\n"
                         "  ring: {density_kg_m3: 7850, mesh: {file: "
                      << data
                      << "mcadring_m1_z48_a20_f5_b005.stl, unit: mm}}\n"
                         "  planets: 3\n"
                         "  carrier: {mass_kg: 0.1, inertia_z_kg_m2: 5.0e-5}\n"
                      << (supports.empty() ? std::string() : "  supports: " + supports + "\n")
                      << "motors: [{joint: sun, target_speed_rad_s: 20, ramp_time_s: 0.01, max_torque_N_m: 5}]\n"
                         "loads: [{joint: carrier, constant_torque_N_m: "
                      << -carrier_load_N_m << ", ramp_time_s: 0.01}]\n";
  return file;
}

}  // namespace gearsim::test
