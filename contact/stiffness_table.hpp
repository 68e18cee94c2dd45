// A measured (or computed) tooth-pair stiffness as a function of where on the flank the contact
// is: single-pair stiffness per face width against the contact point's radius on one gear of the
// pair, interpolated linearly between its rows. The flexible-teeth FE work produces such tables;
// the world's tooth contact (world.cpp) reads the stiffness of each contact from it.
// Plain data and two pure functions: no files (app/ reads the CSV), no Bullet.
#pragma once

#include <string>
#include <vector>

#include "core/result.hpp"

namespace gearsim::contact {

struct StiffnessTable {
  std::string source;  // where it came from (a file), for messages
  std::vector<double> radius_m;  // contact radius on the table's gear, strictly increasing
  std::vector<double> stiffness_N_per_m_per_m;  // single-pair stiffness per face width, > 0, one per radius
};

// Whether a table is sound, else what is wrong: fewer than two rows, columns of unequal length,
// radii not strictly increasing, a stiffness not positive; the refusal's index is the 0-based
// row at fault, or −1 when the fault is not one row's.
Check check_stiffness_table(const StiffnessTable& table);

struct StiffnessLookup {
  double stiffness_N_per_m_per_m = 0;
  bool outside = false;  // the radius lay outside the table: the nearest end row's value
};

// The stiffness at `radius_m`, N/m per m, linear between rows. Outside the table's range: the
// nearest end row's value, and `outside` set (the caller counts it; it is never silent).
StiffnessLookup stiffness_at(const StiffnessTable& table, double radius_m);

}  // namespace gearsim::contact
