// The contact list a search builds from its hits: one contact per (tooth_a, tooth_b, flank_a), the
// deeper of the two probing directions, and the near pairs (gaps) beside them. Included by
// tooth_contact.cpp and coherent_contact.cpp after flank_search_impl.hpp (Hit, kNone): an anonymous
// namespace, as that file.
#pragma once

#include <algorithm>
#include <tuple>
#include <vector>

#include "contact/flank_search_impl.hpp"

namespace gearsim::contact {
namespace {

// Keeps a hit as the contact of (tooth_a, tooth_b, flank_a), the deeper of two for the same key.
// `x_is_a`: the probed gear x is a (pass 0).
// A hit whose depth is not positive (a gap the refinement measured: within the refinement window
// of touching) goes into `near` instead, where given.
void keep_contact(std::vector<ToothContact>& best, int tooth_a, int tooth_b, Flank flank_a, const Hit& h, bool x_is_a,
                  std::vector<ToothContact>* near = nullptr) {
  if (h.depth <= 0 && !(near && h.depth > kNone)) return;
  std::vector<ToothContact>& into = h.depth > 0 ? best : *near;
  ToothContact c;
  c.tooth_a = tooth_a;
  c.tooth_b = tooth_b;
  c.flank_a = flank_a;
  c.depth_m = h.depth;
  // h.normal_into_x is the outward normal of the probed gear y at the point; the contact
  // normal on b points from b toward a.
  c.normal_on_b = x_is_a ? h.normal_into_x : Vector2d(-h.normal_into_x);
  // The probed point lies on x's surface, y's surface lies a depth further along y's outward
  // normal: the overlap's mid-point is half-way.
  c.point_m = h.point + 0.5 * h.depth * h.normal_into_x;
  auto same = [&](const ToothContact& o) { return o.tooth_a == tooth_a && o.tooth_b == tooth_b && o.flank_a == flank_a; };
  auto it = std::find_if(into.begin(), into.end(), same);
  if (it == into.end())
    into.push_back(c);
  else if (it->depth_m < c.depth_m)
    *it = c;
}

// In a fixed order (as the map keyed by teeth and flank gave before), independent of probing order.
void sort_contacts(std::vector<ToothContact>& best) {
  std::sort(best.begin(), best.end(), [](const ToothContact& u, const ToothContact& v) {
    return std::make_tuple(u.tooth_a, u.tooth_b, static_cast<int>(u.flank_a)) <
           std::make_tuple(v.tooth_a, v.tooth_b, static_cast<int>(v.flank_a));
  });
}

// The near hits of tooth pairs that touch (the other probing direction found them overlapping)
// are not near: removed; the rest sorted as the contacts are.
void finish_near(const std::vector<ToothContact>& best, std::vector<ToothContact>* near) {
  if (!near) return;
  std::erase_if(*near, [&](const ToothContact& n) {
    return std::any_of(best.begin(), best.end(),
                       [&](const ToothContact& c) { return c.tooth_a == n.tooth_a && c.tooth_b == n.tooth_b && c.flank_a == n.flank_a; });
  });
  sort_contacts(*near);
}

}  // namespace

}  // namespace gearsim::contact
