#include "models/heightspan/heightspan_section.h"

#include <algorithm>
#include <numbers>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/core/config/fields.h"

namespace repose {

namespace {

const auto kFields = [](auto& v, HeightSpanSpec& x) { heightspan_fields(v, x); };

}  // namespace

void validate(const HeightSpanSpec& s) {
  if (!(s.near_ground_cells >= 0.0 && s.near_ground_cells <= 1e6)) {
    throw FieldError("near_ground_cells", "a number of cells in [0, 1e6]", yaml_number(s.near_ground_cells));
  }
  if (!(s.max_substep_cells > 0.01 && s.max_substep_cells <= 1e6)) {
    throw FieldError("max_substep_cells", "a number of cells in (0.01, 1e6]", yaml_number(s.max_substep_cells));
  }
  if (!(s.max_substep_angle_rad >= 0.01 * kRadPerDeg && s.max_substep_angle_rad <= std::numbers::pi)) {
    throw FieldError("max_substep_angle_deg", "an angle in [0.01, 180] deg",
                     yaml_degrees(s.max_substep_angle_rad / kRadPerDeg));
  }
  if (!(s.bulk_density_kg_m3 > 0.0 && s.bulk_density_kg_m3 <= 1e5)) {
    throw FieldError("bulk_density_kg_m3", "a density in (0, 1e5] kg/m^3", yaml_number(s.bulk_density_kg_m3));
  }
  if (!(s.particle_spread_m_s >= 0.0 && s.particle_spread_m_s <= 100.0)) {
    throw FieldError("particle_spread_m_s", "a speed in [0, 100] m/s", yaml_number(s.particle_spread_m_s));
  }
  if (!(s.release_speed_m_s >= 0.0 && s.release_speed_m_s <= 100.0)) {
    throw FieldError("release_speed_m_s", "a speed in [0, 100] m/s", yaml_number(s.release_speed_m_s));
  }
  if (!(s.intake_layer_m > 0.0 && s.intake_layer_m <= 1e6)) {
    throw FieldError("intake_layer_m", "a height in (0, 1e6] m (1e6: no limit)", yaml_number(s.intake_layer_m));
  }
  if (!(s.intake_fraction > 0.0 && s.intake_fraction <= 1.0)) {
    throw FieldError("intake_fraction", "a fraction in (0, 1] (1: all)", yaml_number(s.intake_fraction));
  }
  if (!(s.wedge_fraction >= 0.0 && s.wedge_fraction <= 1.0)) {
    throw FieldError("wedge_fraction", "a fraction in [0, 1] (0: none)", yaml_number(s.wedge_fraction));
  }
  if (!(s.lip_wedge_fraction >= 0.0 && s.lip_wedge_fraction <= 1.0)) {
    throw FieldError("lip_wedge_fraction", "a fraction in [0, 1] (0: none)", yaml_number(s.lip_wedge_fraction));
  }
  if (!(s.press_fraction >= 0.0 && s.press_fraction <= 1.0)) {
    throw FieldError("press_fraction", "a fraction in [0, 1] (0: compressed)", yaml_number(s.press_fraction));
  }
  if (!(s.press_wedge_fraction >= 0.0 && s.press_wedge_fraction <= 1.0)) {
    throw FieldError("press_wedge_fraction", "a fraction in [0, 1] (0: compressed)", yaml_number(s.press_wedge_fraction));
  }
  if (!(s.side_cut_m >= 0.0 && s.side_cut_m <= 0.1)) {
    throw FieldError("side_cut_m", "a width in [0, 0.1] m (0: none)", yaml_number(s.side_cut_m));
  }
  if (!(s.over_lip_fraction >= 0.0 && s.over_lip_fraction <= 1.0)) {
    throw FieldError("over_lip_fraction", "a fraction in [0, 1] (0: none)", yaml_number(s.over_lip_fraction));
  }
  if (!(s.shear_layer_m >= 0.0 && s.shear_layer_m <= 0.05)) {
    throw FieldError("shear_layer_m", "a thickness in [0, 0.05] m (0: none)", yaml_number(s.shear_layer_m));
  }
  if (s.over_lip_fraction > 0.0 &&
      (!(s.wedge_fraction > 0.0) || s.wedge_source == HeightSpanSpec::WedgeSource::kLip)) {
    throw FieldError("over_lip_fraction", "a share of what the wedge keeps of the drag's compression, which is "
                     "nothing here (wedge_fraction 0 or wedge_source lip): set wedge_fraction above 0 with "
                     "wedge_source compression, both or split, or this to 0", yaml_number(s.over_lip_fraction));
  }
  if (s.lip_wedge_fraction > 0.0 && s.wedge_source != HeightSpanSpec::WedgeSource::kSplit) {
    throw FieldError("lip_wedge_fraction", "read only with wedge_source: split (the other sources take "
                     "wedge_fraction); 0 or set wedge_source: split", yaml_number(s.lip_wedge_fraction));
  }
  if (!(s.frame_interval_s >= 0.0 && s.frame_interval_s <= 1e6)) {
    throw FieldError("frame_interval_s", "a time in [0, 1e6] s (0: no frames)", yaml_number(s.frame_interval_s));
  }
}

void HeightSpanSection::write_yaml(YAML::Emitter& out) const {
  out << YAML::BeginMap;
  FieldWriter writer(out);
  HeightSpanSpec o = options;
  heightspan_fields(writer, o);
  out << YAML::Key << "holds_material" << YAML::Value << YAML::Flow << YAML::BeginMap;
  for (const auto& [name, holds] : holds_material) out << YAML::Key << name << YAML::Value << holds;
  out << YAML::EndMap << YAML::EndMap;
}

std::string HeightSpanSection::summary() const {
  std::string text = fmt::format("heightspan: span maps by {}, near ground {} cells, substeps of {} cells / {:.6g} "
                                 "deg, bulk density {} kg/m^3, frames every {} s",
                                 options.span_maps == HeightSpanSpec::SpanMaps::kCpu ? "cpu" : "osmesa",
                                 options.near_ground_cells, options.max_substep_cells,
                                 options.max_substep_angle_rad / kRadPerDeg, options.bulk_density_kg_m3,
                                 options.frame_interval_s);
  for (const auto& [name, holds] : holds_material) text += fmt::format("; {} {}", name, holds ? "holds" : "holds no material");
  return text;
}

const HeightSpanSection& heightspan_section(const Scene& scene) {
  static const HeightSpanSection defaults;
  const HeightSpanSection* section = scene.section<HeightSpanSection>();
  return section != nullptr ? *section : defaults;
}

Scene with_heightspan(Scene scene, const HeightSpanSection& section) {
  validate(section.options);
  scene.sections[HeightSpanSection::kKey] = std::make_shared<HeightSpanSection>(section);
  return scene;
}

std::shared_ptr<const SceneSection> read_heightspan_section(const YamlValue& value, const Scene& common) {
  auto section = std::make_shared<HeightSpanSection>();
  if (!value.node().IsDefined() || value.node().IsNull()) return section;
  const YamlMap map = value.map(field_keys<HeightSpanSpec>(kFields, {"holds_material"}));
  read_fields_into(map, kFields, section->options);
  validate_at(map, [&] { validate(section->options); });
  if (auto holds = map.get("holds_material")) {
    std::vector<std::string> names;
    for (const ObjectSpec& o : common.objects) names.push_back(o.name);
    const YamlMap objects = holds->map(names);  // unknown object names are errors
    for (const std::string& name : names) {
      if (auto v = objects.get(name)) section->holds_material[name] = v->boolean();
    }
  }
  return section;
}

SectionType heightspan_section_type() {
  return {HeightSpanSection::kKey, "the height-span model's options (models/heightspan/heightspan_section.h)",
          read_heightspan_section, false};
}

}  // namespace repose
