// Reader of CalculiX .dat files: the *NODE PRINT / *EL PRINT blocks (e.g. displacements, forces,
// reaction moments of a reference node). Not a .frd reader.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace gearsim::fe {

// One printed block: "<quantity> (...) for set <SET> and time <t>" followed by rows.
struct DatBlock {
  std::string quantity;  // first word(s) before the parenthesis, e.g. "displacements"
  std::string set;       // node or element set name, upper case as ccx prints it
  double time = 0.0;     // step time of the block
  std::map<int, std::vector<double>> rows;  // node/element id → values, in the deck's units
};

// Parses every block of a .dat; throws InputError for an unreadable file or a malformed row.
std::vector<DatBlock> read_dat(const std::filesystem::path& dat);

// The last block (latest time) with that quantity and set; throws InputError when absent.
const DatBlock& last_block(const std::vector<DatBlock>& blocks, const std::string& quantity,
                           const std::string& set);

}  // namespace gearsim::fe
