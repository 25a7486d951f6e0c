#include "experiments/runner/scene_override.h"

#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/core/config/scene.h"
#include "models/core/config/scene_loader.h"
#include "models/core/config/yaml_reader.h"

namespace repose {
namespace {

// One step of a key path: a map key, or an index into a list.
struct PathStep {
  std::string key;        // set for a map key
  std::size_t index = 0;  // used when key is empty
  bool is_index() const { return key.empty(); }
};

bool is_key_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

std::vector<PathStep> parse_path(const std::string& path) {
  auto bad = [&](const std::string& why) -> std::vector<PathStep> {
    throw InputError(fmt::format("'{}': not a scene key path ({}; expected e.g. ground.cell_size_m or "
                                 "objects[0].motion[1].position_m)",
                                 path, why));
  };
  std::vector<PathStep> steps;
  std::size_t i = 0;
  while (i < path.size()) {
    const std::size_t start = i;
    while (i < path.size() && is_key_char(path[i])) ++i;
    if (i == start) return bad("an empty key");
    steps.push_back({path.substr(start, i - start), 0});
    while (i < path.size() && path[i] == '[') {
      const std::size_t close = path.find(']', i);
      if (close == std::string::npos || close == i + 1) return bad("a malformed [INDEX]");
      const std::string digits = path.substr(i + 1, close - i - 1);
      for (char c : digits) {
        if (std::isdigit(static_cast<unsigned char>(c)) == 0) return bad("an index that is not a number");
      }
      if (digits.size() > 9) return bad("an index too large");
      steps.push_back({"", static_cast<std::size_t>(std::stoul(digits))});
      i = close + 1;
    }
    if (i < path.size()) {
      if (path[i] != '.') return bad(fmt::format("an unexpected '{}'", path[i]));
      if (++i == path.size()) return bad("a trailing '.'");
    }
  }
  if (steps.empty()) return bad("an empty key");
  return steps;
}

std::string prefix_text(const std::vector<PathStep>& steps, std::size_t count) {
  std::string text;
  for (std::size_t k = 0; k < count; ++k) {
    if (steps[k].is_index()) {
      text += fmt::format("[{}]", steps[k].index);
    } else {
      text += (text.empty() ? "" : ".") + steps[k].key;
    }
  }
  return text.empty() ? "scene" : text;
}

}  // namespace

void apply_scene_override(YAML::Node& root, const SceneOverride& override_) {
  const std::vector<PathStep> steps = parse_path(override_.key);
  if (!root.IsMap()) throw InputError("the scene document is not a map");
  // Node::reset rebinds a handle; plain assignment would overwrite the node it refers to.
  YAML::Node current;
  current.reset(root);
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const PathStep& step = steps[k];
    const bool last = k + 1 == steps.size();
    if (step.is_index()) {
      if (!current.IsSequence()) {
        throw InputError(fmt::format("{}: not a list in the scene", prefix_text(steps, k)));
      }
      if (step.index >= current.size()) {
        throw InputError(fmt::format("{}: the list has {} item(s)", prefix_text(steps, k + 1), current.size()));
      }
      if (last) {
        current[step.index] = YAML::Clone(override_.value);
        return;
      }
      YAML::Node next = current[step.index];
      current.reset(next);
      continue;
    }
    if (!current.IsDefined() || current.IsNull()) current = YAML::Node(YAML::NodeType::Map);  // an absent map is created
    if (!current.IsMap()) throw InputError(fmt::format("{}: not a map in the scene", prefix_text(steps, k)));
    if (last) {
      current[step.key] = YAML::Clone(override_.value);
      return;
    }
    YAML::Node next = current[step.key];
    current.reset(next);
  }
}

Scene load_scene_with_overrides(const std::string& scene_path, const std::vector<SceneOverride>& overrides,
                                const SectionTypes& sections) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(scene_path, ec)) throw InputError(scene_path + ": no such scene file");
  YAML::Node root = read_yaml_file(scene_path, input_kind::kScene).node();
  for (const SceneOverride& o : overrides) apply_scene_override(root, o);
  return load_scene_from_node(root, scene_path, sections);
}

}  // namespace repose
