#pragma once
// Overrides of scene keys, applied to a scene file's YAML before it is
// loaded strictly, so an override goes through the same checks as the file:
//
//   ground_model.sweep: false
//   ground.cell_size_m: 0.008
//   objects[0].motion[1].position_m: [0.3, 0, 0.05]
//
// A key is a dotted path of map keys, each optionally followed by [INDEX]
// into a list. A missing map key is created (the strict loader then rejects
// it if the scene format does not know it); an index must exist.

#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "models/core/config/scene.h"
#include "models/core/config/scene_section.h"

namespace repose {

struct SceneOverride {
  std::string key;    // dotted path, as above
  YAML::Node value;   // any YAML value
};

// Sets `value` at `key` inside `root` (a scene document). Throws InputError
// with a message (without a file name) when the path is malformed or does
// not fit the document, e.g. "objects[3]: the list has 1 item".
void apply_scene_override(YAML::Node& root, const SceneOverride& override_);

// Reads the scene file, applies the overrides in order and loads it strictly.
// Errors are the scene loader's (naming the scene file) or apply_scene_override's.
Scene load_scene_with_overrides(const std::string& scene_path, const std::vector<SceneOverride>& overrides,
                                const SectionTypes& sections);

}  // namespace repose
