#pragma once
// The `bullet:` section of a scene (bullet_options.h): optional; a scene without
// it runs with the documented defaults. One field list drives reading, the
// allowed keys, validate() and the resolved copy in the manifest; every
// error is one line naming the file, line and key.

#include "models/core/config/scene_section.h"
#include "validation/bullet/bullet_options.h"

namespace repose {

class BulletSection final : public SceneSection {
 public:
  static constexpr const char* kKey = "bullet";
  BulletOptions options;
  void write_yaml(YAML::Emitter& out) const override;
  std::string summary() const override;
};

// The section's reader (a scene without the key runs with the defaults:
// bullet_options_of; the engine's manifest records the options used).
SectionType bullet_section_type();

// The scene's bullet options: its section's, or the defaults.
BulletOptions bullet_options_of(const Scene& scene);

}  // namespace repose
