#pragma once
// Input checks every reference engine's scene section (liggghts:, bullet:,
// ode:) must pass, written once: a malformed section fails with one line
// naming the key, and in a scene the error names the file, line and key path.

#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "models/core/config/scene.h"
#include "models/core/config/scene_loader.h"
#include "models/core/config/yaml_reader.h"
#include "validation/particles/dem_section.h"

namespace repose::test_support {

// The error of reading `section_yaml` as `type`'s section; "" when accepted.
inline std::string section_error(const SectionType &type, const std::string &section_yaml) {
  try {
    type.read(parse_yaml(section_yaml, "scene.yaml"), Scene{});
  } catch (const InputError &e) {
    return e.what();
  }
  return "";
}

// Each (section, key) is refused with a one-line message naming the key.
inline void expect_one_line_errors_naming_the_key(const SectionType &type,
                                                  const std::vector<std::pair<std::string, std::string>> &cases) {
  for (const auto &[section, key] : cases) {
    const std::string message = section_error(type, section);
    EXPECT_NE(message.find(key), std::string::npos) << section << " -> " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

// A small DEM scene's text, `engine_line` (say "bullet: {time_step_s: 0.5}")
// on its line 4.
inline std::string dem_scene_with(const std::string &engine_line) {
  return "time: {step_s: 0.01, duration_s: 0.1}\n"
         "ground: {extent_m: [0.04, 0.04], cell_size_m: 0.004, initial_height: "
         "{kind: flat, height_m: 0.01}}\n"
         "dem: {bed_depth_m: 0.01}\n" +
         engine_line + "\n";
}

// Loading dem_scene_with(engine_line) fails naming /tmp/scene.yaml:4: and
// `key_path` (say "bullet.time_step_s").
inline void expect_scene_error_names_file_line_and_key(const SectionType &type, const std::string &engine_line,
                                                       const std::string &key_path) {
  try {
    load_scene_from_string(dem_scene_with(engine_line), "/tmp/scene.yaml", {dem_section_type(), type});
    ADD_FAILURE() << "accepted " << engine_line;
  } catch (const InputError &e) {
    EXPECT_NE(std::string(e.what()).find("/tmp/scene.yaml:4:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(key_path), std::string::npos) << e.what();
  }
}

}  // namespace repose::test_support
