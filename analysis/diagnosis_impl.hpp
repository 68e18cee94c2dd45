// The template body of diagnose_from_contacts (diagnosis.hpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <sstream>

namespace gearsim {

template <class LoadedFlank>
Diagnosis diagnose_from_contacts(const std::vector<ToothLoads>& loads, LoadedFlank loaded_flank_of) {
  Diagnosis d;
  // Faults: a share below the gear's other teeth in its own mesh.
  for (const ToothLoads& t : loads)
    for (int k : t.share_flagged) {
      const auto ku = static_cast<std::size_t>(k);
      if (!(t.share_z[ku] < 0)) continue;
      int lowest = 0;
      for (const std::vector<double>& rev : t.share_per_revolution)
        lowest += static_cast<int>(std::min_element(rev.begin(), rev.end()) - rev.begin()) == k;
      ToothFault f;
      f.gear = t.gear;
      f.tooth = k;
      f.flank = loaded_flank_of(t.pair, t.gear);
      f.pair = t.pair;
      f.source = "contact forces";
      double others = 0;
      for (std::size_t j = 0; j < t.share_steps.size(); ++j)
        if (j != ku) others += t.share_steps[j];
      others /= static_cast<double>(t.share_steps.size() - 1);
      std::ostringstream ev;
      ev.precision(3);
      ev << "in its mesh " << t.pair.a << "–" << t.pair.b << " it carried " << 100 * t.share_steps[ku] / others
         << " % of the share a sound tooth of " << t.gear << " carries (share z " << t.share_z[ku] << ", mean load z " << t.z_score[ku]
         << "), the least of its teeth in " << lowest << " of " << t.share_per_revolution.size() << " revolutions";
      f.evidence = ev.str();
      f.confidence =
          t.share_per_revolution.empty() ? 0.0 : static_cast<double>(lowest) / static_cast<double>(t.share_per_revolution.size());
      d.faults.push_back(f);
    }
  auto is_fault = [&](const std::string& gear, int tooth) {
    return std::any_of(d.faults.begin(), d.faults.end(), [&](const ToothFault& f) { return f.gear == gear && f.tooth == tooth; });
  };
  auto next_to_fault = [&](const ToothLoads& t, int k) {
    const int z = static_cast<int>(t.share_steps.size());
    return std::any_of(d.faults.begin(), d.faults.end(), [&](const ToothFault& f) {
      return f.gear == t.gear && f.pair == t.pair && ((f.tooth + 1) % z == k || (f.tooth + z - 1) % z == k);
    });
  };
  // Responses: teeth that stand out by mean load or by a raised share, and are no fault.
  for (const ToothLoads& t : loads) {
    std::vector<int> standing = t.flagged;
    for (int k : t.share_flagged) standing.push_back(k);
    std::sort(standing.begin(), standing.end());
    standing.erase(std::unique(standing.begin(), standing.end()), standing.end());
    for (int k : standing) {
      const auto ku = static_cast<std::size_t>(k);
      if (is_fault(t.gear, k)) continue;
      ToothResponse r{t.gear, k, t.pair, t.z_score[ku], t.share_z[ku], "contact forces", ""};
      double others = 0;
      for (std::size_t j = 0; j < t.share_steps.size(); ++j)
        if (j != ku) others += t.share_steps[j];
      others /= static_cast<double>(t.share_steps.size() - 1);
      const double rel = others > 0 ? t.share_steps[ku] / others - 1 : 0.0;
      std::ostringstream why;
      why.precision(3);
      if (rel > 0 && next_to_fault(t, k))
        why << "next to a faulty tooth of the same gear in the same mesh: it takes up the share that tooth sheds (share " << 100 * rel
            << " % above a sound tooth's, share z " << t.share_z[ku] << ")";
      else if (std::abs(rel) < t.min_relative_deviation || std::abs(t.share_z[ku]) < t.z_threshold)
        why << "its mean load stands out (z " << t.z_score[ku] << ") but its share of its own mesh is within " << 100 * std::abs(rel)
            << " % of a sound tooth's (a fault is called at " << 100 * t.min_relative_deviation << " %): its mesh as a whole carried "
            << (t.z_score[ku] > 0 ? "more" : "less")
            << " load while it was in mesh, as meshes sharing one load do when a tooth elsewhere sheds or takes load "
               "(planets meshing in phase, or the other mesh of a planet whose tooth sheds load)";
      else
        why << "its share of its mesh stands " << 100 * rel << " % off a sound tooth's (share z " << t.share_z[ku]
            << ") without a fault beside it: not explained by this diagnosis";
      r.reason = why.str();
      d.responses.push_back(r);
    }
  }
  return d;
}

}  // namespace gearsim
