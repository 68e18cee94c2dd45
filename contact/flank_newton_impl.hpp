// Internal to contact/, included by flank_refine_impl.hpp only (after Hit and XY): Newton's
// method on the smooth (C¹) flanks for a contact's deepest point — an interior maximum of the
// overlap (newton_hit) or a flank's corner (corner_hit). docs/tooth-contact.md, "Newton
// refinement on smooth flanks". Not an interface.
#pragma once

namespace gearsim::contact {
namespace {

// Newton's method on the smooth flanks (FlankTable::flank_jet): the deepest point of x's flank
// (tooth k, f) inside y's facing flank, started at radius r0 and kept within [r_lo, r_hi]. The
// unknowns are the radius r on x's flank and s on y's; with P(r), Q(s) both in y's frame:
//   F1 = (P − Q)·Q' = 0      (Q is the foot of the normal from P),
//   F2 = P' × Q'   = 0      (the flanks parallel there: the depth along x's flank stationary),
// and a maximum, not a minimum, of the depth D = (Q − P)·n_y (n_y: y's outward normal). Iterates
// until a step moves both points by less than kNewtonTolerance_m. No hit (depth kNone) when the
// start faces no flank of y, a point leaves the flanks' material, r leaves [r_lo, r_hi], the
// stationary point is not a maximum, or kNewtonIterations do not converge: the caller falls
// back to the sampled refinement then.
constexpr double kNewtonTolerance_m = 1e-13;
constexpr int kNewtonIterations = 12;
// A Newton step shorter than xy.taylor_step_m on both flanks (kNewtonTaylor_m,
// flank_search_impl.hpp) ends the iteration at the point it leads to, taken from the curves'
// second-order expansions (the jets just evaluated) instead of evaluating the flanks there once
// more, where the step after it, from F at that point on the expansions, falls below
// kNewtonTolerance_m and both points stay within one cubic of their flank (the expansions' own
// error is then of order |P'''|·h³). Newton's method converges quadratically: from a step h the
// next is about K·h²; K measured on the paper run (dt 1e-5 s, first steps of 1–100 nm) lies
// mostly between 1e2 and 1e4 per m, with a tail to 1e9 (flat maxima), which the check on the
// next step keeps from ending early. A continued contact's first step, from the prediction, is
// mostly below 0.1 µm at the paper run's step: one evaluation of the two flanks instead of two.

// A solved contact: x's point P, the foot Q on y's flank (tooth j, flank g) with y's outward
// normal n there, all in y's frame; the hit in world terms.
Hit solved_hit(const XY& xy, const Vector2d& P, const Vector2d& Q, const Vector2d& n, int j, Flank g) {
  Hit h;
  h.depth = (Q - P).dot(n);
  h.point = xy.y.to_world(P);
  h.normal_into_x = xy.y.dir_to_world(n);
  h.tooth_y = j;
  h.flank_y = g;
  return h;
}

// Whether a flank curve with derivatives d1, d2 (FlankTable::FlankJet) curves less sharply than a
// circle of `radius` (m): its radius of curvature |d1|³ / |d1 × d2| (+∞ where it is straight)
// above it, compared as |d1|⁶ > radius²·(d1 × d2)², without a root or a division.
bool curvature_radius_above(const Vector2d& d1, const Vector2d& d2, double radius) {
  const double c = d1.x() * d2.y() - d1.y() * d2.x(), n2 = d1.squaredNorm();
  return n2 * n2 * n2 > radius * radius * (c * c);
}

// y's flank that x's point P (y's frame) faces, and the start of the search for its foot there
// (the flank point at P's own radius). False where P faces no flank.
struct Facing {
  int tooth = -1;
  Flank flank = Flank::Ccw;
  double s = 0;
};
bool facing_flank(const FlankTable& yt, const Vector2d& P, Facing* out) {
  const FlankTable::Probe start = yt.probe_depth(P);
  if (!start.has_flank) return false;
  *out = {start.tooth, start.flank, P.norm()};
  return true;
}

// newton_hit() with the foot's flank (tooth j, g) and its start s0 given.
Hit newton_solve(const XY& xy, int k, Flank f, double r0, int j, Flank g, double s0, double r_lo, double r_hi) {
  const FlankTable &xt = xy.x.table, &yt = xy.y.table;
  FlankTable::FlankJet a, b;
  double r = r0, s = s0;
  for (int it = 0; it < kNewtonIterations; ++it) {
    if (!xt.flank_jet(k, f, r, &a) || !yt.flank_jet(j, g, s, &b)) return {};
    const Vector2d P = xy.in_y(a.point), P1 = xy.rot * a.d1, P2 = xy.rot * a.d2;
    const Vector2d &Q = b.point, &Q1 = b.d1, &Q2 = b.d2;
    auto cross = [](const Vector2d& u, const Vector2d& v) { return u.x() * v.y() - u.y() * v.x(); };
    const Vector2d PQ = P - Q;
    const double F1 = PQ.dot(Q1), F2 = cross(P1, Q1);
    const double J11 = P1.dot(Q1), J12 = -Q1.squaredNorm() + PQ.dot(Q2), J21 = cross(P2, Q1), J22 = cross(P1, Q2);
    const double det = J11 * J22 - J12 * J21;
    if (!(std::abs(det) > 0)) return {};
    const double dr = -(F1 * J22 - F2 * J12) / det, ds = -(J11 * F2 - J21 * F1) / det;
    // The solution at (r + hr, s + hs), where the curves' second-order expansions at (r, s) put
    // P, P' and Q, Q' at Pt, P1t and Qt, Q1t (hr = hs = 0: exactly the evaluated point).
    auto solution = [&](double hr, double hs, const Vector2d& Pt, const Vector2d& P1t, const Vector2d& Qt, const Vector2d& Q1t) -> Hit {
      // At the foot: D(r) = (Q(s(r)) − P(r))·n_y, dD/dr = −P'·n_y, and
      // d²D/dr² = −P''·n_y − P'·(dn_y/ds)·(ds/dr) with ds/dr = −J11/J12 (F1 held at 0), where
      // n_y = σ·t/|t| (t = Q1t turned a quarter, σ = ±1 by the flank) and
      // dn_y/ds = σ·(t'/|t| − t·(Q1t·Q2)/|t|³), t' = Q2 turned a quarter. Its sign from
      // d²D/dr²·|t|³·J12² = −σ·(P''·t)·|t|²·J12² + σ·(P'·(t'·|t|² − t·(Q1t·Q2)))·J11·J12,
      // without a root or a division.
      const double j11 = P1t.dot(Q1t), j12 = -Q1t.squaredNorm() + (Pt - Qt).dot(Q2);
      const Vector2d t(-Q1t.y(), Q1t.x()), t1(-Q2.y(), Q2.x());
      const double sigma = g == Flank::Ccw ? 1.0 : -1.0, q2 = Q1t.squaredNorm();
      const double d2_scaled = sigma * (-P2.dot(t) * q2 * (j12 * j12) + P1t.dot(t1 * q2 - t * Q1t.dot(Q2)) * j11 * j12);
      if (!(d2_scaled < 0) || !(j12 != 0)) return {};
      // FlankTable::outward_normal(g, Q1t).
      const double q1 = Q1t.norm();
      const Vector2d n = g == Flank::Ccw ? Vector2d(t / q1) : Vector2d(-(t / q1));
      Hit h = solved_hit(xy, Pt, Qt, n, j, g);
      const double spacing = xy.spacing_m;  // x's probe spacing (Hit::gentle)
      h.gentle = curvature_radius_above(a.d1 + hr * a.d2, a.d2, spacing) && curvature_radius_above(Q1t, Q2, spacing);
      h.solved = Hit::kInterior;
      h.r_x = r + hr;
      h.s_y = s + hs;
      return h;
    };
    if (std::abs(dr) < kNewtonTolerance_m && std::abs(ds) < kNewtonTolerance_m) return solution(0, 0, P, P1, Q, Q1);
    if (std::abs(dr) < xy.taylor_step_m && std::abs(ds) < xy.taylor_step_m) {
      double s_lo, s_hi;
      yt.flank_extent(j, g, &s_lo, &s_hi);
      if (r + dr >= r_lo && r + dr <= r_hi && s + ds >= s_lo && s + ds <= s_hi && xt.same_interval(r, r + dr) &&
          yt.same_interval(s, s + ds)) {
        // The step after this one, from F at (r + dr, s + ds) on the expansions and this J:
        // where it falls below the tolerance, (r + dr, s + ds) is as converged as a further
        // evaluation of the flanks would show. Only within one cubic of each flank, where the
        // expansions hold to |P'''|·h³ (a knot between would add its jump of P'' times h²).
        const Vector2d Pt = P + dr * (P1 + (0.5 * dr) * P2), P1t = P1 + dr * P2;
        const Vector2d Qt = Q + ds * (Q1 + (0.5 * ds) * Q2), Q1t = Q1 + ds * Q2;
        const double G1 = (Pt - Qt).dot(Q1t), G2 = cross(P1t, Q1t);
        const double dr2 = -(G1 * J22 - G2 * J12) / det, ds2 = -(J11 * G2 - J21 * G1) / det;
        if (std::abs(dr2) < kNewtonTolerance_m && std::abs(ds2) < kNewtonTolerance_m) return solution(dr, ds, Pt, P1t, Qt, Q1t);
      }
    }
    r += dr;
    s += ds;
    if (!(r >= r_lo && r <= r_hi)) return {};
  }
  return {};
}

Hit newton_hit(const XY& xy, int k, Flank f, double r0, double r_lo, double r_hi) {
  FlankTable::FlankJet a;
  Facing y_flank;
  if (!xy.x.table.flank_jet(k, f, r0, &a) || !facing_flank(xy.y.table, xy.in_y(a.point), &y_flank)) return {};
  return newton_solve(xy, k, f, r0, y_flank.tooth, y_flank.flank, y_flank.s, r_lo, r_hi);
}

// The depth of x's flank end at r_end (its tip corner, or its root end) inside y's facing flank:
// the foot of the normal by Newton's method on F1 alone. No hit unless the depth still rises
// toward that end there (dD/dr = −P'·n_y > 0 at a high end, < 0 at a low end): the maximum is
// then the corner itself.
// corner_hit() with the foot's flank (tooth j, g) and its start s0 given.
Hit corner_solve(const XY& xy, int k, Flank f, double r_end, bool high_end, int j, Flank g, double s0) {
  const FlankTable &xt = xy.x.table, &yt = xy.y.table;
  FlankTable::FlankJet a, b;
  if (!xt.flank_jet(k, f, r_end, &a)) return {};
  const Vector2d P = xy.in_y(a.point), P1 = xy.rot * a.d1;
  double s = s0;
  for (int it = 0; it < kNewtonIterations; ++it) {
    if (!yt.flank_jet(j, g, s, &b)) return {};
    const Vector2d PQ = P - b.point;
    const double F1 = PQ.dot(b.d1), dF = -b.d1.squaredNorm() + PQ.dot(b.d2);
    if (!(dF < 0)) return {};
    const double ds = -F1 / dF;
    // The foot at s + hs from y's curve's second-order expansion at s (hs = 0: the evaluated
    // point), as in newton_solve().
    auto solution = [&](double hs) -> Hit {
      const Vector2d Qt = b.point + hs * (b.d1 + (0.5 * hs) * b.d2), Q1t = b.d1 + hs * b.d2;
      const Vector2d n = FlankTable::outward_normal(g, Q1t);
      const double rise = -P1.dot(n);
      if (!(high_end ? rise > 0 : rise < 0)) return {};
      Hit h = solved_hit(xy, P, Qt, n, j, g);
      const double spacing = xy.spacing_m;  // x's probe spacing (Hit::gentle)
      h.gentle = curvature_radius_above(a.d1, a.d2, spacing) && curvature_radius_above(Q1t, b.d2, spacing);
      h.solved = high_end ? Hit::kCornerHigh : Hit::kCornerLow;
      h.r_x = r_end;
      h.s_y = s + hs;
      return h;
    };
    if (std::abs(ds) < kNewtonTolerance_m) return solution(0);
    if (std::abs(ds) < xy.taylor_step_m) {
      double s_lo, s_hi;
      yt.flank_extent(j, g, &s_lo, &s_hi);
      if (s + ds >= s_lo && s + ds <= s_hi && yt.same_interval(s, s + ds)) {
        // The step after this one, from F1 at s + ds on the expansion (as newton_solve()).
        const Vector2d Qt = b.point + ds * (b.d1 + (0.5 * ds) * b.d2), Q1t = b.d1 + ds * b.d2;
        if (std::abs((P - Qt).dot(Q1t) / dF) < kNewtonTolerance_m) return solution(ds);
      }
    }
    s += ds;
  }
  return {};
}

Hit corner_hit(const XY& xy, int k, Flank f, double r_end, bool high_end) {
  FlankTable::FlankJet a;
  Facing y_flank;
  if (!xy.x.table.flank_jet(k, f, r_end, &a) || !facing_flank(xy.y.table, xy.in_y(a.point), &y_flank)) return {};
  return corner_solve(xy, k, f, r_end, high_end, y_flank.tooth, y_flank.flank, y_flank.s);
}

}  // namespace
}  // namespace gearsim::contact
