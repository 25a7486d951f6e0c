#include "validation/liggghts/liggghts_section.h"

#include <fmt/format.h>

#include "models/core/config/fields.h"
#include "models/core/config/scene.h"

namespace repose {

namespace {

const auto kLiggghtsFields = [](auto& v, LiggghtsOptions& o) { liggghts_option_fields(v, o); };

std::shared_ptr<const SceneSection> read_liggghts_section(const YamlValue& value, const Scene&) {
  auto section = std::make_shared<LiggghtsSection>();
  if (value.node().IsDefined() && !value.node().IsNull()) {
    const YamlMap map = value.map(field_keys<LiggghtsOptions>(kLiggghtsFields));
    read_fields_into(map, kLiggghtsFields, section->options);
    validate_at(map, [&] { validate(section->options); });
  }
  return section;
}

}  // namespace

void LiggghtsSection::write_yaml(YAML::Emitter& out) const { write_fields_map(out, options, kLiggghtsFields); }

std::string LiggghtsSection::summary() const {
  return fmt::format("liggghts: neighbour skin {} radii, list checked every {} steps, sorted every {} steps",
                     options.neighbor_skin_radii, options.neighbor_check_every_steps, options.sort_every_steps);
}

SectionType liggghts_section_type() {
  return {LiggghtsSection::kKey, "how LIGGGHTS finds contacts (validation/liggghts/liggghts_options.h)",
          read_liggghts_section, false};
}

LiggghtsOptions liggghts_options_of(const Scene& scene) {
  const LiggghtsSection* section = scene.section<LiggghtsSection>();
  return section ? section->options : LiggghtsOptions{};
}

}  // namespace repose
