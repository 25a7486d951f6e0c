#include "models/snow/snow_section.h"

#include <algorithm>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/core/config/fields.h"

namespace repose {

namespace {

const auto kSnowFields = [](auto& v, SnowSpec& x) { snow_fields(v, x); };

std::vector<SnowGroupSpec> read_groups(const YamlValue& value, const Scene& common) {
  std::vector<SnowGroupSpec> groups;
  for (const YamlValue& item : value.list(1)) {
    const YamlMap map = item.map({"name", "ground", "objects"});
    SnowGroupSpec g;
    g.name = map.required("name", "a group name").string();
    if (auto ground = map.get("ground")) g.ground = ground->boolean();
    if (auto objects = map.get("objects")) {
      for (const YamlValue& o : objects->list(1)) {
        const std::string name = o.string();
        const bool known = std::any_of(common.objects.begin(), common.objects.end(),
                                       [&](const ObjectSpec& s) { return s.name == name; });
        if (!known) o.fail("the name of one of the scene's objects");
        g.objects.push_back(name);
      }
    }
    groups.push_back(std::move(g));
  }
  return groups;
}

SnowfallRate read_snowfall(const YamlValue& value) {
  std::vector<SnowfallKeyframe> keyframes;
  for (const YamlValue& item : value.list(1)) {
    const YamlMap map = item.map({"time_s", "rate_m_s"});
    keyframes.push_back({map.number("time_s", Range::any()), map.number("rate_m_s", Range::non_negative())});
  }
  for (std::size_t k = 1; k < keyframes.size(); ++k) {
    if (!(keyframes[k].time_s > keyframes[k - 1].time_s)) {
      value.list()[k].fail("a keyframe whose time_s is later than the one before");
    }
  }
  return SnowfallRate(std::move(keyframes));
}

}  // namespace

void SnowSection::write_yaml(YAML::Emitter& out) const {
  out << YAML::BeginMap;
  FieldWriter writer(out);
  SnowSpec s = spec;
  snow_fields(writer, s);
  out << YAML::Key << "groups" << YAML::Value << YAML::BeginSeq;
  for (const SnowGroupSpec& g : spec.options.groups) {
    out << YAML::Flow << YAML::BeginMap << YAML::Key << "name" << YAML::Value << g.name;
    if (g.ground) out << YAML::Key << "ground" << YAML::Value << true;
    if (!g.objects.empty()) out << YAML::Key << "objects" << YAML::Value << YAML::Flow << g.objects;
    out << YAML::EndMap;
  }
  out << YAML::EndSeq << YAML::Key << "snowfall" << YAML::Value << YAML::BeginSeq;
  for (const SnowfallKeyframe& k : spec.options.snowfall.keyframes()) {
    out << YAML::Flow << YAML::BeginMap << YAML::Key << "time_s" << YAML::Value << yaml_number(k.time_s)
        << YAML::Key << "rate_m_s" << YAML::Value << yaml_number(k.rate_m_s) << YAML::EndMap;
  }
  out << YAML::EndSeq;
  if (!spec.options.pictures.times_s.empty()) {
    out << YAML::Key << "picture_times_s" << YAML::Value << YAML::Flow << YAML::BeginSeq;
    for (const double t : spec.options.pictures.times_s) out << yaml_number(t);
    out << YAML::EndSeq;
  }
  out << YAML::EndMap;
}

std::string SnowSection::summary() const {
  const SnowOptions& o = spec.options;
  return fmt::format("snow: {} group(s), {} directions around tilt {:.6g} deg azimuth {:.6g} deg, spread {:.6g} deg, "
                     "repose angle {:.6g} deg, {} renderer",
                     o.groups.size(), o.direction_count, o.main_direction.tilt_rad / kRadPerDeg,
                     o.main_direction.azimuth_rad / kRadPerDeg, spec.params.direction_spread_rad / kRadPerDeg,
                     spec.params.repose_angle_rad / kRadPerDeg, o.renderer == SnowRenderer::kCpu ? "cpu" : "osmesa");
}

std::shared_ptr<const SceneSection> read_snow_section(const YamlValue& value, const Scene& common) {
  auto section = std::make_shared<SnowSection>();
  const YamlMap map = value.map(field_keys<SnowSpec>(kSnowFields, {"groups", "snowfall", "snowfall_rate_m_s", "picture_times_s"}));
  read_fields_into(map, kSnowFields, section->spec);
  section->spec.options.groups = read_groups(map.required("groups", "a list of snow groups"), common);
  if (map.has("snowfall") && map.has("snowfall_rate_m_s")) {
    map.fail_missing("snowfall", "either snowfall_rate_m_s or snowfall, not both");
  }
  if (auto rate = map.get("snowfall_rate_m_s")) section->spec.options.snowfall = SnowfallRate(rate->number(Range::non_negative()));
  if (auto keyframes = map.get("snowfall")) section->spec.options.snowfall = read_snowfall(*keyframes);
  if (auto times = map.get("picture_times_s")) {
    for (const YamlValue& t : times->list(0)) section->spec.options.pictures.times_s.push_back(t.number(Range::any()));
  }
  validate_at(map, [&] {
    validate(section->spec.options);
    validate_picture_times(section->spec.options.pictures, common.time.duration_s);
    validate(section->spec.params);
  });
  return section;
}

SectionType snow_section_type() {
  return {SnowSection::kKey, "the snow model's groups, snowfall and options (models/snow/snow_section.h)",
          read_snow_section, false};
}

Scene with_snow(Scene scene, const SnowSpec& spec) {
  validate(spec.options);
  validate(spec.params);
  auto section = std::make_shared<SnowSection>();
  section->spec = spec;
  scene.sections[SnowSection::kKey] = section;
  return scene;
}

}  // namespace repose
