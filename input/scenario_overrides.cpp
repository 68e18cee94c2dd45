// --set overrides of a scenario: "a.b[2].c=value" edits the parsed YAML tree before validation.
// Values are built as fresh nodes without a file position, so an error about them names the
// file and the key path (never a misleading line), and blame_override() adds the override text.
#include <cctype>
#include <charconv>

#include "input/scenario_parts.hpp"
#include "core/errors.hpp"

namespace gearsim::input::scenario_detail {
namespace {

// One component of an override path: a mapping key, optionally indexing the list it holds.
struct Step {
  std::string key;
  std::optional<std::size_t> index;
};

[[noreturn]] void bad(const std::string& file, const std::string& text, const std::string& why) {
  throw InputError(file + ": --set '" + text + "': " + why);
}

std::vector<Step> parse_path(const std::string& path, const std::string& file, const std::string& text) {
  std::vector<Step> steps;
  std::size_t start = 0;
  while (true) {
    const std::size_t dot = path.find('.', start);
    std::string part = path.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    Step s;
    if (const std::size_t open = part.find('['); open != std::string::npos) {
      const std::string digits = part.substr(open + 1, part.size() - open - 2);
      std::size_t i = 0;
      const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), i);
      if (part.back() != ']' || digits.empty() || ec != std::errc() || end != digits.data() + digits.size())
        bad(file, text, "expected a list index as name[N] with N a whole number, got '" + part + "'");
      s.index = i;
      part = part.substr(0, open);
    }
    if (part.empty() || part.find_first_of("[]= ") != std::string::npos)
      bad(file, text, "expected a key path such as solver.time_step_s or bodies[0].mass_kg");
    s.key = part;
    steps.push_back(s);
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  return steps;
}

// A deep copy without file positions (yaml-cpp's code-built nodes carry a null mark).
YAML::Node unmarked(const YAML::Node& n) {
  switch (n.Type()) {
    case YAML::NodeType::Scalar:
      return YAML::Node(n.Scalar());
    case YAML::NodeType::Sequence: {
      YAML::Node out(YAML::NodeType::Sequence);
      for (const YAML::Node& item : n) out.push_back(unmarked(item));
      return out;
    }
    case YAML::NodeType::Map: {
      YAML::Node out(YAML::NodeType::Map);
      for (const auto& kv : n) out[kv.first.Scalar()] = unmarked(kv.second);
      return out;
    }
    default:
      return YAML::Node(YAML::NodeType::Null);
  }
}

// Sets steps[i..] below `node` (a mapping) to `value`, creating missing mappings on the way.
void set_path(YAML::Node node, const std::vector<Step>& steps, std::size_t i, const YAML::Node& value, const std::string& file,
              const std::string& text) {
  const Step& s = steps[i];
  const bool last = i + 1 == steps.size();
  if (!node.IsMap()) bad(file, text, "'" + steps[i - 1].key + "' does not hold a mapping, cannot set '" + s.key + "' in it");
  if (s.index) {
    YAML::Node list = node[s.key];
    if (!list.IsSequence()) bad(file, text, "'" + s.key + "' is not a list in the file");
    if (*s.index >= list.size())
      bad(file, text, "'" + s.key + "' has " + std::to_string(list.size()) + " items, no item " + std::to_string(*s.index));
    YAML::Node item = list[*s.index];
    if (last)
      item = value;  // yaml-cpp: assigning to a bound node replaces its content in place
    else
      set_path(item, steps, i + 1, value, file, text);
    return;
  }
  if (last) {
    node[s.key] = value;
    return;
  }
  if (!node[s.key].IsDefined() || node[s.key].IsNull()) node[s.key] = YAML::Node(YAML::NodeType::Map);
  set_path(node[s.key], steps, i + 1, value, file, text);
}

// Path text of an override ("a.b[2].c"), or "" when it has no '='.
std::string path_of(const std::string& text) {
  const std::size_t eq = text.find('=');
  return eq == std::string::npos ? "" : text.substr(0, eq);
}

}  // namespace

void apply_overrides(YAML::Node& root, const std::vector<std::string>& overrides, const std::string& file) {
  for (const std::string& text : overrides) {
    const std::size_t eq = text.find('=');
    if (eq == std::string::npos) bad(file, text, "expected key.path=value");
    const std::string path = text.substr(0, eq);
    const std::vector<Step> steps = parse_path(path, file, text);
    YAML::Node parsed;
    try {
      parsed = YAML::Load(text.substr(eq + 1));
    } catch (const YAML::Exception& e) {
      bad(file, text, "the value is not valid YAML: " + e.msg);
    }
    // Its keys, size and depth checked as a file's are, before unmarked() copies (and so would
    // expand) its aliases.
    try {
      check_yaml_tree(parsed, "the value");
    } catch (const InputError& e) {
      bad(file, text, e.what());
    }
    const YAML::Node value = unmarked(parsed);
    set_path(root, steps, 0, value, file, text);
  }
}

std::string blame_override(const std::string& message, const std::vector<std::string>& overrides) {
  // The longest override path (or a prefix of one, e.g. the body an override changed) that the
  // message names as its key path; of overrides setting the same key, the last, whose value
  // stands (apply_overrides() applies them in order).
  for (auto it = overrides.rbegin(); it != overrides.rend(); ++it) {
    const std::string& text = *it;
    std::string p = path_of(text);
    while (!p.empty()) {
      if (message.find(" " + p + ":") != std::string::npos) return message + " (set by --set '" + text + "')";
      const std::size_t cut = p.find_last_of('.');
      if (cut == std::string::npos) break;
      p = p.substr(0, cut);
    }
  }
  return message;
}

}  // namespace gearsim::input::scenario_detail
