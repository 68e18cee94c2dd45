#include "contact/tooth_contact.hpp"

#include <vector>

#include "contact/contact_list_impl.hpp"
#include "contact/flank_search_impl.hpp"

namespace gearsim::contact {

std::vector<ToothContact> find_tooth_contacts(const FlankTable& ta, const PlanarPose& pa, const FlankTable& tb, const PlanarPose& pb) {
  std::vector<ToothContact> found;
  find_tooth_contacts(ta, pa, tb, pb, found);
  return found;
}

void find_tooth_contacts(const FlankTable& ta, const PlanarPose& pa, const FlankTable& tb, const PlanarPose& pb,
                         std::vector<ToothContact>& best, std::vector<ToothContact>* near) {
  const Frame a{ta, pa}, b{tb, pb};
  // One per (tooth_a, tooth_b, flank of a): the deepest of both probing directions.
  best.clear();
  if (near) near->clear();
  for (int pass = 0; pass < 2; ++pass) {
    const Frame& x = pass == 0 ? a : b;
    const Frame& y = pass == 0 ? b : a;
    const XY xy{x, y};
    const ToothWindow window = tooth_window(x, y);
    int hint = -1;
    for_each_tooth(window, x.table.teeth(), [&](int k) {
      if (!tooth_near(x, k, y)) return;
      for (Flank f : {Flank::Ccw, Flank::Cw}) {
        // An overlap of two teeth is deepest either along a's flank (a's tip corner included)
        // or at b's tip corner: a's flanks are probed whole, b's only at their tips.
        const Hit h = deepest_on_flank(xy, k, f, pass == 1, hint);
        if (h.tooth_y < 0) continue;
        // Name the contact by a's tooth and the flank of a that is touched.
        if (pass == 0)
          keep_contact(best, k, h.tooth_y, f, h, true, near);
        else
          keep_contact(best, h.tooth_y, k, h.flank_y, h, false, near);
      }
    });
  }
  sort_contacts(best);
  finish_near(best, near);
}

}  // namespace gearsim::contact
