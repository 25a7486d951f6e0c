#pragma once
// The `ode:` section of a scene (ode_options.h): optional; a scene without
// it runs with the documented defaults. One field list drives reading, the
// allowed keys, validate() and the resolved copy in the manifest; every
// error is one line naming the file, line and key.

#include "models/core/config/scene_section.h"
#include "validation/ode/ode_options.h"

namespace repose {

class OdeSection final : public SceneSection {
 public:
  static constexpr const char* kKey = "ode";
  OdeOptions options;
  void write_yaml(YAML::Emitter& out) const override;
  std::string summary() const override;
};

// The section's reader (a scene without the key runs with the defaults:
// ode_options_of; the engine's manifest records the options used).
SectionType ode_section_type();

// The scene's ode options: its section's, or the defaults.
OdeOptions ode_options_of(const Scene& scene);

}  // namespace repose
