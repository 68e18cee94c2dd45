// Reader of CalculiX .dat files: the *NODE PRINT / *EL PRINT blocks (e.g. displacements, forces,
// reaction moments of a reference node). Not a .frd reader.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace gearsim::fe {

// One printed block: "<quantity> (...) for set <SET> and time <t>" followed by rows.
struct DatBlock {
  std::string quantity;  // first word(s) before the parenthesis, e.g. "displacements"
  std::string set;  // node or element set name, upper case as ccx prints it
  double time = 0.0;  // step time of the block
  std::map<int, std::vector<double>> rows;  // node/element id → values, in the deck's units
  // Every row in file order (an *EL PRINT block has one row per integration point, all with the
  // element's id: the integration point number is the first value).
  std::vector<std::pair<int, std::vector<double>>> row_list;
};

// One "statistics for slave set S, master set M" block of a *CONTACT PRINT CF request: the total
// contact force the master exerts on the slave surface, in the deck's units.
struct ContactTotals {
  std::string slave, master;  // surface names, upper case as ccx prints them
  double time = 0.0;  // total time of the block
  double force[3] = {0, 0, 0};  // fx, fy, fz on the slave surface
  double moment[3] = {0, 0, 0};  // about the origin
  double centre[3] = {0, 0, 0};  // centre of gravity of the contact area
  double normal_force = 0, shear_force = 0, area = 0;  // normal (+ = tension), shear size, area
};

// Every contact-statistics block of a .dat; throws InputError for a malformed block.
std::vector<ContactTotals> read_contact_totals(const std::filesystem::path& dat);

// Parses every block of a .dat; throws InputError for an unreadable file or a malformed row.
std::vector<DatBlock> read_dat(const std::filesystem::path& dat);

// The last block (latest time) with that quantity and set; throws InputError when absent.
const DatBlock& last_block(const std::vector<DatBlock>& blocks, const std::string& quantity, const std::string& set);

}  // namespace gearsim::fe
