// Flank tables shared by their exact inputs: building one (sampling every flank of every tooth)
// is most of the set-up of a run, and a run's identical gears (a planetary's planets), the cases
// of a sweep and the runs of a process build the same tables again and again. A table is a pure
// function of (loop, layout, internal, samples), so one built from bit-identical inputs is the
// table a fresh build would give: runs are the same with or without the store. Thread-safe (the
// sweep's workers share it); tables are immutable once built.
#pragma once

#include <cstddef>
#include <memory>

#include "contact/flank_table.hpp"

namespace gearsim::contact {

// The table FlankTable(loop, layout, internal, samples) builds, from the store when an earlier
// call had the same inputs bit for bit (then also the same object). Throws as the constructor does.
std::shared_ptr<const FlankTable> shared_flank_table(const Polygon2& loop, const ToothLayout& layout, bool internal, int samples);

// The store keeps the most recently used tables up to this many bytes (estimated from their
// sizes); a table in use elsewhere stays alive through its shared_ptr either way.
constexpr std::size_t kFlankTableStoreBytes = std::size_t{64} << 20;

// Tables the store holds now, and how many calls it answered from them since the start (tests).
struct FlankTableStoreStats {
  std::size_t tables = 0, bytes = 0;
  long hits = 0, builds = 0;
};
FlankTableStoreStats flank_table_store_stats();

}  // namespace gearsim::contact
