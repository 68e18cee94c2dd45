#include "physics/row_solvers.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>

// The active set's warm start from the last step's bound states, and Bullet's Dantzig solver,
// the fallback of every row solve (docs/solver.md, "The row solve").
namespace gearsim::physics {

// Bullet's Dantzig solver reports failure through one global flag (btDantzigLCP.cpp, s_error):
// worlds stepped in parallel threads (the Python module releases the GIL) take turns.
std::mutex& dantzig_flag() {
  static std::mutex m;
  return m;
}

// Each row's identity — a tooth contact's rows are the same rows while its tooth pair and flank
// stay in contact, a joint's rows are always the same — and its bound state in the step before.
void ActiveSetSolve::warm_start(const RowSystem& rows, const std::vector<ContactSample>& contacts) {
  const std::size_t n = rows.rows.size();
  std::swap(keys_, keys_before_);
  std::swap(states_, states_before_);
  keys_.resize(n);
  states_.assign(n, RowBound::free);
  for (std::size_t i = 0; i < n; ++i) {
    const MultibodyRow& r = rows.rows[i];
    std::array<int, 5> key{static_cast<int>(r.kind), r.owner, 0, 0, 0};
    if (r.kind == MultibodyRow::contact_normal || r.kind == MultibodyRow::contact_friction) {
      const ContactSample& c = contacts[static_cast<std::size_t>(r.owner)];
      key = {static_cast<int>(r.kind), c.pair, c.geometry.tooth_a, c.geometry.tooth_b, static_cast<int>(c.geometry.flank_a)};
    } else {
      for (std::size_t j = 0; j < i; ++j)  // a bearing's two radial rows: its first and second
        if (keys_[j][0] == key[0] && keys_[j][1] == key[1]) key[2] = std::max(key[2], keys_[j][2] + 1);
    }
    keys_[i] = key;
    // The row's state in the step before: at the same place in the list, or anywhere in it.
    if (i < keys_before_.size() && keys_before_[i] == key) {
      states_[i] = states_before_[i];
    } else {
      const auto it = std::find(keys_before_.begin(), keys_before_.end(), key);
      if (it != keys_before_.end()) states_[i] = states_before_[static_cast<std::size_t>(it - keys_before_.begin())];
    }
  }
}

int ActiveSetSolve::solve_dense(RowSystem& rows) {
  return solve_row_lcp(static_cast<int>(rows.rows.size()), rows.a.data(), rows.b.data(), rows.lo.data(), rows.hi.data(), rows.findex.data(),
                       rows.x.data(), states_.data(), lcp_);
}

void ActiveSetSolve::start_cold(RowSystem& rows) {
  std::fill(rows.x.begin(), rows.x.end(), 0.0);
  std::fill(states_.begin(), states_.end(), RowBound::free);  // the next step starts cold
}

bool DantzigSolve::solve(RowSystem& rows, bool fixed_friction) {
  const std::lock_guard<std::mutex> lock(dantzig_flag());
  if (fixed_friction) return solve_fixed_friction(rows);
  return btSolveDantzigLCP(static_cast<int>(rows.rows.size()), rows.a.data(), rows.x.data(), rows.b.data(), rows.w.data(), 0,
                           rows.lo.data(), rows.hi.data(), rows.findex.data(), scratch_);
}

// Dantzig for rows some of which are friction fixed at a multiple of their normal's impulse
// (verify.friction_model sliding: lo = hi on a row with findex ≥ 0). Bullet's solver takes such a
// row's bounds as ±|hi·x_f|, a box, so the fixed rows leave its problem: their impulses c·x_f,
// with x_f from the last round, move to the others' right-hand side, and rounds repeat until the
// impulses settle (each round changes the normals by about μ times the last change: a
// contraction). The caller holds dantzig_flag(). false when a round fails or they do not settle.
bool DantzigSolve::solve_fixed_friction(RowSystem& rows) {
  const int n = static_cast<int>(rows.rows.size());
  const auto at = [](int i) { return static_cast<std::size_t>(i); };
  std::vector<int> kept, fixed, slot(at(n), -1);
  for (int i = 0; i < n; ++i) {
    if (rows.held_friction(at(i)))
      fixed.push_back(i);
    else
      slot[at(i)] = static_cast<int>(kept.size()), kept.push_back(i);
  }
  const int m = static_cast<int>(kept.size());
  std::vector<double> a(at(m) * at(m)), b(at(m)), x(at(m)), w(at(m)), lo(at(m)), hi(at(m));
  std::vector<int> findex(at(m));
  std::fill(rows.x.begin(), rows.x.begin() + n, 0.0);
  constexpr int kRounds = 50;
  for (int round = 0; round < kRounds; ++round) {
    for (const int t : fixed) rows.x[at(t)] = rows.lo[at(t)] * rows.x[at(rows.findex[at(t)])];
    for (int r = 0; r < m; ++r) {
      const int i = kept[at(r)];
      for (int c = 0; c < m; ++c) a[at(r) * at(m) + at(c)] = rows.a[at(i) * at(n) + at(kept[at(c)])];
      b[at(r)] = rows.b[at(i)];
      for (const int t : fixed) b[at(r)] -= rows.a[at(i) * at(n) + at(t)] * rows.x[at(t)];
      lo[at(r)] = rows.lo[at(i)], hi[at(r)] = rows.hi[at(i)];
      findex[at(r)] = rows.findex[at(i)] >= 0 ? slot[at(rows.findex[at(i)])] : -1;
      x[at(r)] = 0, w[at(r)] = 0;
    }
    if (!btSolveDantzigLCP(m, a.data(), x.data(), b.data(), w.data(), 0, lo.data(), hi.data(), findex.data(), scratch_)) return false;
    double change = 0, scale = 0;
    for (int r = 0; r < m; ++r) {
      const std::size_t i = at(kept[at(r)]);
      change = std::max(change, std::abs(x[at(r)] - rows.x[i]));
      scale = std::max(scale, std::abs(x[at(r)]));
      rows.x[i] = x[at(r)];
    }
    if (change <= 1e-12 * scale) {
      for (const int t : fixed) rows.x[at(t)] = rows.lo[at(t)] * rows.x[at(rows.findex[at(t)])];
      return true;
    }
  }
  return false;
}

}  // namespace gearsim::physics
