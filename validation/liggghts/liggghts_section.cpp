#include "validation/liggghts/liggghts_section.h"

#include <fmt/format.h>

#include "models/core/config/fields.h"
#include "models/core/config/scene.h"
#include "validation/particles/option_fields.h"

namespace repose {

namespace {

const auto kLiggghtsFields = [](auto& v, LiggghtsOptions& o) { liggghts_option_fields(v, o); };

}  // namespace

void LiggghtsSection::write_yaml(YAML::Emitter& out) const { write_fields_map(out, options, kLiggghtsFields); }

std::string LiggghtsSection::summary() const {
  return fmt::format("liggghts: neighbour skin {} radii, list checked every {} steps, sorted every {} steps",
                     options.neighbor_skin_radii, options.neighbor_check_every_steps, options.sort_every_steps);
}

SectionType liggghts_section_type() {
  auto read = [](const YamlValue& value, const Scene&) {
    return read_option_section<LiggghtsSection>(value, kLiggghtsFields);
  };
  return {LiggghtsSection::kKey,
          "how LIGGGHTS finds contacts (validation/liggghts/liggghts_options.h)", read, false};
}

LiggghtsOptions liggghts_options_of(const Scene& scene) { return options_of<LiggghtsSection>(scene); }

}  // namespace repose
