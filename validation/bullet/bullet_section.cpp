#include "validation/bullet/bullet_section.h"

#include <fmt/format.h>

#include "models/core/config/fields.h"
#include "models/core/config/scene.h"
#include "validation/particles/option_fields.h"

namespace repose {

namespace {

const auto kBulletFields = [](auto& v, BulletOptions& o) { bullet_option_fields(v, o); };

}  // namespace

void BulletSection::write_yaml(YAML::Emitter& out) const { write_fields_map(out, options, kBulletFields); }

std::string BulletSection::summary() const {
  return fmt::format("bullet: step {:.4g} s, {} solver iterations", options.rigid.time_step_s, options.rigid.solver_iterations);
}

SectionType bullet_section_type() {
  auto read = [](const YamlValue& value, const Scene&) {
    return read_option_section<BulletSection>(value, kBulletFields);
  };
  return {BulletSection::kKey,
          "the Bullet rigid-body reference's options (validation/bullet/bullet_options.h)", read, false};
}

BulletOptions bullet_options_of(const Scene& scene) { return options_of<BulletSection>(scene); }

}  // namespace repose
