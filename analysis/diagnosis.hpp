// A diagnosis from the per-tooth contact loads that tells a fault from its consequences. A
// tooth is a fault when its share of its own mesh (ToothLoads::share_steps) stands below its
// gear's other teeth: its flank is not where the geometry puts it, so within the very mesh it
// belongs to it carries less than a sound tooth does at the same roll positions. Teeth whose mean
// load stands out while their share of their mesh is sound are responses: their mesh as a whole
// carried more or less (planets meshing in phase hand each other the load a flawed tooth sheds);
// teeth whose share stands above the rest next to a fault are its neighbours taking up its share.
#pragma once

#include <string>
#include <vector>

#include "analysis/tooth_loads.hpp"

namespace gearsim {

struct ToothFault {
  std::string gear;  // body name, e.g. "planet_0"
  int tooth = -1;  // its own numbering
  std::string flank;  // "ccw" or "cw": the flank that carried the load in that mesh ("" unknown)
  PairId pair;  // the mesh it was found in
  std::string source;  // "contact forces"
  std::string evidence;
  // The fraction of the window's whole revolutions in which this tooth carried the smallest share
  // of its gear's teeth in that mesh (1: every revolution).
  double confidence = 0;
};

struct ToothResponse {
  std::string gear;
  int tooth = -1;
  PairId pair;
  double load_z = 0, share_z = 0;  // contact forces; NaN for a sensor's response
  std::string source = "contact forces";
  std::string reason;
};

struct Diagnosis {
  std::vector<ToothFault> faults;  // empty: nothing found
  std::vector<ToothResponse> responses;  // teeth that stand out for a fault elsewhere
};

// `loaded_flank_of` gives, for a logged pair and one of its gears, the flank that carried the
// load ("ccw"/"cw", "" unknown).
template <class LoadedFlank>
Diagnosis diagnose_from_contacts(const std::vector<ToothLoads>& loads, LoadedFlank loaded_flank_of);

}  // namespace gearsim

#include "analysis/diagnosis_impl.hpp"
