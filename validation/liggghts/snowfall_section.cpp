#include "validation/liggghts/snowfall_section.h"

#include <fmt/format.h>

#include "validation/particles/option_fields.h"

namespace repose {

namespace {

const auto kSnowfallFields = [](auto& v, SnowfallOptions& o) { snowfall_option_fields(v, o); };

}  // namespace

void validate(const SnowfallOptions& options) {
  OptionFieldChecker checker;
  snowfall_option_fields(checker, options);
}

void SnowfallSection::write_yaml(YAML::Emitter& out) const { write_fields_map(out, options, kSnowfallFields); }

std::string SnowfallSection::summary() const {
  return fmt::format("dem_snowfall: {} streams at {} m/s over {} s, packing {}", options.stream_count,
                     options.fall_speed_m_s, options.insert_time_s, options.packing_fraction);
}

SectionType snowfall_section_type() {
  auto read = [](const YamlValue& value, const Scene&) {
    return read_option_section<SnowfallSection>(value, kSnowfallFields);
  };
  return {SnowfallSection::kKey, "how the DEM snowfall reference rains its grains (validation/liggghts/snowfall_section.h)",
          read, false};
}

SnowfallOptions snowfall_options_of(const Scene& scene) { return options_of<SnowfallSection>(scene); }

}  // namespace repose
