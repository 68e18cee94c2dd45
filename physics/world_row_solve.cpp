#include <algorithm>

#include "physics/world_impl.hpp"

// solver.row_solver active_set (docs/solver.md, "The row solve"): the step's rows solved by
// physics/row_lcp.hpp from the bound states the same rows had in the step before — a tooth
// contact's rows are the same rows while its tooth pair and flank stay in contact, a joint's rows
// are always the same — falling back to Dantzig (world_multibody.cpp) when that does not settle.
namespace gearsim::physics {

bool World::Impl::solve_rows_active_set() {
  MultibodyEngine& e = *mb;
  const std::size_t n = e.rows.size();
  std::swap(e.row_keys, e.row_keys_before);
  std::swap(e.row_states, e.row_states_before);
  e.row_keys.resize(n);
  e.row_states.assign(n, RowBound::free);
  for (std::size_t i = 0; i < n; ++i) {
    const MultibodyRow& r = e.rows[i];
    std::array<int, 5> key{static_cast<int>(r.kind), r.owner, 0, 0, 0};
    if (r.kind == MultibodyRow::contact_normal || r.kind == MultibodyRow::contact_friction) {
      const ContactSample& c = contacts[static_cast<std::size_t>(r.owner)];
      key = {static_cast<int>(r.kind), c.pair, c.geometry.tooth_a, c.geometry.tooth_b, static_cast<int>(c.geometry.flank_a)};
    } else {
      for (std::size_t j = 0; j < i; ++j)  // a bearing's two radial rows: its first and second
        if (e.row_keys[j][0] == key[0] && e.row_keys[j][1] == key[1]) key[2] = std::max(key[2], e.row_keys[j][2] + 1);
    }
    e.row_keys[i] = key;
    // The row's state in the step before: at the same place in the list, or anywhere in it.
    if (i < e.row_keys_before.size() && e.row_keys_before[i] == key) {
      e.row_states[i] = e.row_states_before[i];
    } else {
      const auto it = std::find(e.row_keys_before.begin(), e.row_keys_before.end(), key);
      if (it != e.row_keys_before.end()) e.row_states[i] = e.row_states_before[static_cast<std::size_t>(it - e.row_keys_before.begin())];
    }
  }
  const int solves = e.planar_mass ? solve_rows_planar()
                                   : solve_row_lcp(static_cast<int>(n), e.a.data(), e.b.data(), e.lo.data(), e.hi.data(), e.findex.data(),
                                                   e.x.data(), e.row_states.data(), e.lcp);
  if (solves > 0) {
    ++profile.active_set_solves;
    return true;
  }
  std::fill(e.x.begin(), e.x.end(), 0.0);
  std::fill(e.row_states.begin(), e.row_states.end(), RowBound::free);  // the next step starts cold
  return false;
}

}  // namespace gearsim::physics
