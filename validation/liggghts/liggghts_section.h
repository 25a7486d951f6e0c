#pragma once
// The `liggghts:` section of a scene (liggghts_options.h): optional; a scene
// without it runs with the documented defaults. One field list drives
// reading, the allowed keys, validate() and the resolved copy in the
// manifest; every error is one line naming the file, line and key.

#include "models/core/config/scene_section.h"
#include "validation/liggghts/liggghts_options.h"

namespace repose {

class LiggghtsSection final : public SceneSection {
 public:
  static constexpr const char* kKey = "liggghts";
  LiggghtsOptions options;
  void write_yaml(YAML::Emitter& out) const override;
  std::string summary() const override;
};

SectionType liggghts_section_type();

// The scene's liggghts options: its section's, or the defaults.
LiggghtsOptions liggghts_options_of(const Scene& scene);

}  // namespace repose
