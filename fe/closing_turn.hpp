// The turn that brings two rigid gears from clear into touch (or backs an overlap out): a search
// on a "touching" predicate of one body's rotation, by steps of kClosingStep_rad then bisection to
// kClosingTolerance_rad. The geometric closing of a quasi-static FE position (planetary and spur
// pair). Not a contact model: the predicate (a flank-table probe) decides what touching means.
#pragma once

#include <functional>
#include <string>

namespace gearsim::fe {

// The smallest turn δ (in `sense`, ±1) at which touching(δ) turns true, when touching(0) is false;
// when touching(0) is true, the turn against `sense` at which it turns false, returned on its
// touching side. Throws InputError naming `who` when nothing changes within kMaxClosingTurn_rad.
double closing_turn(const std::function<bool(double)>& touching, double sense, const std::string& who);

}  // namespace gearsim::fe
