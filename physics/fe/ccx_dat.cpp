#include "physics/fe/ccx_dat.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>

#include "geometry/errors.hpp"

namespace gearsim::fe {

std::vector<DatBlock> read_dat(const std::filesystem::path& dat) {
  std::ifstream in(dat);
  if (!in) throw InputError("cannot read ccx output " + dat.string());
  std::vector<DatBlock> blocks;
  std::string line;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    // A block header names its set and time.
    const size_t fs = line.find(" for set ");
    const size_t at = line.find(" and time ");
    if (fs != std::string::npos && at != std::string::npos) {
      DatBlock b;
      std::string q = line.substr(0, std::min(line.find('('), fs));
      q.erase(0, q.find_first_not_of(' '));
      q.erase(q.find_last_not_of(' ') + 1);
      b.quantity = q;
      b.set = line.substr(fs + 9, at - fs - 9);
      b.time = std::stod(line.substr(at + 10));
      blocks.push_back(std::move(b));
      continue;
    }
    // Rows: an integer id and numbers, under the latest header.
    std::istringstream row(line);
    int id = 0;
    if (blocks.empty() || !(row >> id)) continue;
    std::vector<double> v;
    std::string tok;
    while (row >> tok) {
      try {
        v.push_back(std::stod(tok));
      } catch (const std::exception&) {
        throw InputError(dat.string() + ":" + std::to_string(line_no) + ": expected numbers, got '" +
                         tok + "'");
      }
    }
    blocks.back().rows[id] = v;
  }
  return blocks;
}

const DatBlock& last_block(const std::vector<DatBlock>& blocks, const std::string& quantity,
                           const std::string& set) {
  auto upper = [](std::string s) {
    for (auto& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
  };
  for (auto it = blocks.rbegin(); it != blocks.rend(); ++it)
    if (it->quantity == quantity && upper(it->set) == upper(set)) return *it;
  throw InputError("ccx output has no '" + quantity + "' block for set " + set);
}

}  // namespace gearsim::fe
