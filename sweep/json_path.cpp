#include "sweep/json_path.hpp"

#include <charconv>

#include "core/errors.hpp"

namespace gearsim::sweep {

using json = nlohmann::ordered_json;

const json* find_json_path(const json& doc, const std::string& path) {
  const json* at = &doc;
  std::size_t i = 0;
  while (i < path.size()) {
    if (path[i] == '[') {  // an item of a list: [N]
      const std::size_t close = path.find(']', i);
      std::size_t n = 0;
      if (close == std::string::npos || !at->is_array()) return nullptr;
      const auto [end, ec] = std::from_chars(path.data() + i + 1, path.data() + close, n);
      if (ec != std::errc() || end != path.data() + close || n >= at->size()) return nullptr;
      at = &(*at)[n];
      i = close + 1;
    } else {  // a key: the longest one of this object that the path continues from
      if (path[i] == '.') ++i;
      if (!at->is_object()) return nullptr;
      const json* best = nullptr;
      std::size_t best_len = 0;
      for (const auto& [key, value] : at->items()) {
        const std::size_t end = i + key.size();
        const bool fits =
            key.size() > best_len && path.compare(i, key.size(), key) == 0 && (end == path.size() || path[end] == '.' || path[end] == '[');
        if (fits) best = &value, best_len = key.size();
      }
      if (!best) return nullptr;
      at = best;
      i += best_len;
    }
  }
  return at;
}

json number_at_path(const json& doc, const std::string& path, const std::string& file) {
  const json* v = find_json_path(doc, path);
  if (!v) throw InputError(file + ": key " + path + ": not there (collect names a key path of this file)");
  if (!v->is_number() && !v->is_null())
    throw InputError(file + ": key " + path + ": expected a number, got " + std::string(v->type_name()));
  return *v;
}

}  // namespace gearsim::sweep
