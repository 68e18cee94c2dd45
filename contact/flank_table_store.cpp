#include "contact/flank_table_store.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <list>
#include <mutex>
#include <vector>

namespace gearsim::contact {
namespace {

struct Entry {
  std::vector<Eigen::Vector2d> points;
  ToothLayout layout;
  bool internal = false;
  int samples = 0;
  std::uint64_t hash = 0;
  std::size_t bytes = 0;
  std::shared_ptr<const FlankTable> table;
};

// FNV-1a over the inputs' bytes: a quick filter; entries are compared in full.
std::uint64_t hash_of(const Polygon2& loop, const ToothLayout& layout, bool internal, int samples) {
  std::uint64_t h = 1469598103934665603ull;
  auto add = [&h](const void* p, std::size_t n) {
    const auto* c = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i < n; ++i) h = (h ^ c[i]) * 1099511628211ull;
  };
  add(loop.points.data(), loop.points.size() * sizeof(Eigen::Vector2d));
  add(&layout.teeth, sizeof layout.teeth);
  add(&layout.tooth0_angle_rad, sizeof layout.tooth0_angle_rad);
  add(&internal, sizeof internal);
  add(&samples, sizeof samples);
  return h;
}

bool same_inputs(const Entry& e, const Polygon2& loop, const ToothLayout& layout, bool internal, int samples) {
  auto same_bits = [](double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; };
  return e.layout.teeth == layout.teeth && same_bits(e.layout.tooth0_angle_rad, layout.tooth0_angle_rad) && e.internal == internal &&
         e.samples == samples && e.points.size() == loop.points.size() &&
         std::memcmp(e.points.data(), loop.points.data(), loop.points.size() * sizeof(Eigen::Vector2d)) == 0;
}

// What a table holds, bytes, roughly: its rows (angle, knot and rise data per sample), its
// per-tooth probe points and the loop kept here as the key.
std::size_t bytes_of(const FlankTable& t, std::size_t loop_points, int samples) {
  const std::size_t rows = static_cast<std::size_t>(t.distinct_teeth()), teeth = static_cast<std::size_t>(t.teeth());
  return loop_points * sizeof(Eigen::Vector2d) + rows * static_cast<std::size_t>(samples) * (2 * sizeof(double) + 6 * sizeof(double)) +
         teeth * (2 * FlankTable::kProbeRadii * sizeof(Eigen::Vector2d) + 64);
}

struct Store {
  std::mutex mutex;
  std::list<Entry> entries;  // most recently used first
  std::size_t bytes = 0;
  long hits = 0, builds = 0;
};

Store& store() {
  static Store s;
  return s;
}

}  // namespace

std::shared_ptr<const FlankTable> shared_flank_table(const Polygon2& loop, const ToothLayout& layout, bool internal, int samples) {
  Store& s = store();
  const std::uint64_t h = hash_of(loop, layout, internal, samples);
  {
    const std::lock_guard<std::mutex> lock(s.mutex);
    for (auto it = s.entries.begin(); it != s.entries.end(); ++it)
      if (it->hash == h && same_inputs(*it, loop, layout, internal, samples)) {
        s.entries.splice(s.entries.begin(), s.entries, it);
        ++s.hits;
        return it->table;
      }
  }
  // Built outside the lock (another worker may build the same table meanwhile: the first kept wins).
  auto table = std::make_shared<const FlankTable>(loop, layout, internal, samples);
  const std::lock_guard<std::mutex> lock(s.mutex);
  ++s.builds;
  for (auto it = s.entries.begin(); it != s.entries.end(); ++it)
    if (it->hash == h && same_inputs(*it, loop, layout, internal, samples)) return it->table;
  Entry e{loop.points, layout, internal, samples, h, bytes_of(*table, loop.points.size(), samples), table};
  s.bytes += e.bytes;
  s.entries.push_front(std::move(e));
  while (s.bytes > kFlankTableStoreBytes && s.entries.size() > 1) {
    s.bytes -= s.entries.back().bytes;
    s.entries.pop_back();
  }
  return table;
}

FlankTableStoreStats flank_table_store_stats() {
  Store& s = store();
  const std::lock_guard<std::mutex> lock(s.mutex);
  return {s.entries.size(), s.bytes, s.hits, s.builds};
}

}  // namespace gearsim::contact
