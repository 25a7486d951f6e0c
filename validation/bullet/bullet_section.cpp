#include "validation/bullet/bullet_section.h"

#include <fmt/format.h>

#include "models/core/config/fields.h"
#include "models/core/config/scene.h"

namespace repose {

namespace {

const auto kBulletFields = [](auto& v, BulletOptions& o) { bullet_option_fields(v, o); };

std::shared_ptr<const SceneSection> read_bullet_section(const YamlValue& value, const Scene&) {
  auto section = std::make_shared<BulletSection>();
  if (value.node().IsDefined() && !value.node().IsNull()) {
    const YamlMap map = value.map(field_keys<BulletOptions>(kBulletFields));
    read_fields_into(map, kBulletFields, section->options);
    validate_at(map, [&] { validate(section->options); });
  }
  return section;
}

}  // namespace

void BulletSection::write_yaml(YAML::Emitter& out) const { write_fields_map(out, options, kBulletFields); }

std::string BulletSection::summary() const {
  return fmt::format("bullet: step {:.4g} s, {} solver iterations", options.rigid.time_step_s, options.rigid.solver_iterations);
}

SectionType bullet_section_type() {
  return {BulletSection::kKey, "the Bullet rigid-body reference's options (validation/bullet/bullet_options.h)", read_bullet_section,
          false};
}

BulletOptions bullet_options_of(const Scene& scene) {
  const BulletSection* section = scene.section<BulletSection>();
  return section ? section->options : BulletOptions{};
}

}  // namespace repose
