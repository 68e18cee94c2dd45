#include "fe/ccx_dat.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>

#include "core/errors.hpp"

namespace gearsim::fe {

std::vector<DatBlock> read_dat(const std::filesystem::path& dat) {
  std::ifstream in(dat);
  if (!in) throw InputError("cannot read ccx output " + dat.string());
  std::vector<DatBlock> blocks;
  std::string line;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    // Contact statistics are read by read_contact_totals; skip their numbers here.
    if (line.find("statistics for slave set") != std::string::npos) {
      blocks.push_back(DatBlock{"contact statistics", "", 0.0, {}, {}});
      continue;
    }
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
    if (blocks.empty() || blocks.back().quantity == "contact statistics") continue;
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
        throw InputError(dat.string() + ":" + std::to_string(line_no) + ": expected numbers, got '" + tok + "'");
      }
    }
    blocks.back().rows[id] = v;
    blocks.back().row_list.emplace_back(id, std::move(v));
  }
  return blocks;
}

std::vector<ContactTotals> read_contact_totals(const std::filesystem::path& dat) {
  std::ifstream in(dat);
  if (!in) throw InputError("cannot read ccx output " + dat.string());
  std::vector<ContactTotals> out;
  std::string line;
  int line_no = 0;
  // Numeric lines of the current block, in order: force+moment, centre+normal, moment about
  // the centre, area+normal+shear.
  std::vector<std::vector<double>> rows;
  auto finish = [&] {
    if (out.empty() || rows.empty()) return;
    if (rows.size() < 4 || rows[0].size() < 6 || rows[1].size() < 3 || rows[3].size() < 3)
      throw InputError(dat.string() + ":" + std::to_string(line_no) + ": incomplete contact statistics block");
    ContactTotals& c = out.back();
    for (int k = 0; k < 3; ++k) {
      c.force[k] = rows[0][k];
      c.moment[k] = rows[0][3 + k];
      c.centre[k] = rows[1][k];
    }
    c.area = rows[3][0];
    c.normal_force = rows[3][1];
    c.shear_force = rows[3][2];
    rows.clear();
  };
  bool inside = false;
  while (std::getline(in, line)) {
    ++line_no;
    const size_t h = line.find("statistics for slave set ");
    if (h != std::string::npos) {
      finish();
      ContactTotals c;
      const size_t comma = line.find(", master set ");
      const size_t at = line.find(" and time ");
      if (comma == std::string::npos || at == std::string::npos)
        throw InputError(dat.string() + ":" + std::to_string(line_no) + ": unreadable header");
      c.slave = line.substr(h + 25, comma - h - 25);
      c.master = line.substr(comma + 13, at - comma - 13);
      c.time = std::stod(line.substr(at + 10));
      out.push_back(c);
      inside = true;
      continue;
    }
    if (!inside) continue;
    // A header of another kind ends the block.
    if (line.find(" for set ") != std::string::npos) {
      finish();
      inside = false;
      continue;
    }
    std::istringstream row(line);
    std::vector<double> v;
    std::string tok;
    bool numeric = true;
    while (row >> tok) {
      try {
        size_t used = 0;
        v.push_back(std::stod(tok, &used));
        if (used != tok.size()) numeric = false;
      } catch (const std::exception&) {
        numeric = false;
      }
      if (!numeric) break;
    }
    if (numeric && !v.empty()) rows.push_back(v);
  }
  finish();
  return out;
}

const DatBlock& last_block(const std::vector<DatBlock>& blocks, const std::string& quantity, const std::string& set) {
  auto upper = [](std::string s) {
    for (auto& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
  };
  for (auto it = blocks.rbegin(); it != blocks.rend(); ++it)
    if (it->quantity == quantity && upper(it->set) == upper(set)) return *it;
  throw InputError("ccx output has no '" + quantity + "' block for set " + set);
}

}  // namespace gearsim::fe
