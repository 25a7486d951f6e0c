#include "models/terrain/terrain_section.h"

#include <filesystem>

#include <fmt/format.h>

#include "models/core/config/fields.h"
#include "models/core/config/scene.h"
#include "models/terrain/key_contour_file.h"

namespace repose {

namespace {

const auto kOptionFields = [](auto& v, TerrainOptions& o) { terrain_option_fields(v, o); };

Polygon2 read_points(const YamlValue& value) {
  Polygon2 points;
  for (const YamlValue& p : value.list(3)) points.push_back(p.vec2(Range::any()));
  return points;
}

std::vector<KeyContour> read_inline_contours(const YamlValue& list) {
  std::vector<KeyContour> contours;
  for (const YamlValue& item : list.list(1)) {
    const YamlMap m = item.map({"name", "height_m", "points_m"});
    contours.push_back({m.string_or("name", item.display_path()), read_points(m.required("points_m", "a list of [x, y]")),
                        m.number("height_m", Range::any())});
  }
  return contours;
}

ElementSource read_elements(const YamlValue& value) {
  const YamlMap m = value.map({"region_m", "gap_fraction", "radius_spread", "position_jitter", "layers"});
  ElementSource src;
  src.region_m = read_points(m.required("region_m", "a list of [x, y]"));
  src.gap_fraction = m.number_or("gap_fraction", Range::right_open(0.0, 1.0), src.gap_fraction);
  src.radius_spread = m.number_or("radius_spread", Range::right_open(0.0, 1.0), src.radius_spread);
  src.position_jitter = m.number_or("position_jitter", Range::closed(0.0, 1.0), src.position_jitter);
  for (const YamlValue& item : m.required("layers", "a list of layers").list(1)) {
    const YamlMap l = item.map({"name", "radius_m", "rows", "friction", "restitution", "density_kg_m3", "rolling_friction"});
    ElementLayer layer;
    layer.name = l.string_or("name", item.display_path());
    layer.radius_m = l.number("radius_m", Range::positive());
    layer.rows = static_cast<int>(l.integer_or("rows", IntRange{1, 1000}, layer.rows));
    layer.friction = l.number_or("friction", Range::non_negative(), layer.friction);
    layer.restitution = l.number_or("restitution", Range::closed(0.0, 1.0), layer.restitution);
    layer.density_kg_m3 = l.number_or("density_kg_m3", Range::positive(), layer.density_kg_m3);
    layer.rolling_friction = l.number_or("rolling_friction", Range::non_negative(), layer.rolling_friction);
    src.layers.push_back(layer);
  }
  return src;
}

BuildingFootprint read_building(const YamlValue& value) {
  const YamlMap m = value.map(
      {"name", "footprint_m", "storeys", "storey_height_m", "gap_m", "bulk_density_kg_m3", "joint_break_force_n"});
  BuildingFootprint b;
  b.name = m.string_or("name", value.display_path());
  b.polygon_m = read_points(m.required("footprint_m", "a list of [x, y]"));
  b.storeys = static_cast<int>(m.integer_or("storeys", IntRange{1, 1000}, b.storeys));
  b.storey_height_m = m.number_or("storey_height_m", Range::positive(), b.storey_height_m);
  b.gap_m = m.number_or("gap_m", Range::non_negative(), b.gap_m);
  b.bulk_density_kg_m3 = m.number_or("bulk_density_kg_m3", Range::positive(), b.bulk_density_kg_m3);
  b.joint_break_force_n = m.number_or("joint_break_force_n", Range::positive(), b.joint_break_force_n);
  return b;
}

std::vector<KeyContour> read_key_contours_of(const YamlMap& m, const YamlValue& section) {
  const std::optional<YamlValue> inline_contours = m.get("key_contours");
  const std::optional<YamlValue> contour_file = m.get("key_contours_file");
  if (inline_contours.has_value() == contour_file.has_value()) {
    m.fail_missing("key_contours", "exactly one of key_contours and key_contours_file");
  }
  if (inline_contours) return read_inline_contours(*inline_contours);
  std::filesystem::path path(contour_file->string());
  if (path.is_relative()) path = std::filesystem::path(section.file()).parent_path() / path;
  return read_key_contours(path.string());
}

void write_points(YAML::Emitter& out, const char* key, const Polygon2& points) {
  out << YAML::Key << key << YAML::Value << YAML::Flow << YAML::BeginSeq;
  for (const Point2& p : points) out << YAML::Flow << YAML::BeginSeq << yaml_number(p.x()) << yaml_number(p.y()) << YAML::EndSeq;
  out << YAML::EndSeq;
}

void write_elements(YAML::Emitter& out, const ElementSource& e) {
  out << YAML::Key << "elements" << YAML::Value << YAML::BeginMap;
  write_points(out, "region_m", e.region_m);
  out << YAML::Key << "gap_fraction" << YAML::Value << yaml_number(e.gap_fraction);
  out << YAML::Key << "radius_spread" << YAML::Value << yaml_number(e.radius_spread);
  out << YAML::Key << "position_jitter" << YAML::Value << yaml_number(e.position_jitter);
  out << YAML::Key << "layers" << YAML::Value << YAML::BeginSeq;
  for (const ElementLayer& l : e.layers) {
    out << YAML::Flow << YAML::BeginMap << YAML::Key << "name" << YAML::Value << l.name << YAML::Key << "radius_m"
        << YAML::Value << yaml_number(l.radius_m) << YAML::Key << "rows" << YAML::Value << l.rows << YAML::Key
        << "friction" << YAML::Value << yaml_number(l.friction) << YAML::Key << "restitution" << YAML::Value
        << yaml_number(l.restitution) << YAML::Key << "density_kg_m3" << YAML::Value << yaml_number(l.density_kg_m3)
        << YAML::Key << "rolling_friction" << YAML::Value << yaml_number(l.rolling_friction) << YAML::EndMap;
  }
  out << YAML::EndSeq << YAML::EndMap;
}

}  // namespace

TerrainScene read_terrain_section(const YamlValue& section) {
  const YamlMap m = section.map(
      field_keys<TerrainOptions>(kOptionFields, {"key_contours", "key_contours_file", "elements", "buildings"}));
  TerrainScene scene;
  scene.key_contours = read_key_contours_of(m, section);
  read_fields_into(m, kOptionFields, scene.options);
  validate_at(m, [&] { scene.options.validate(); });
  if (const auto e = m.get("elements")) scene.elements = read_elements(*e);
  if (const auto b = m.get("buildings")) {
    for (const YamlValue& item : b->list()) scene.buildings.push_back(read_building(item));
  }
  scene.validate();
  return scene;
}

void TerrainSection::write_yaml(YAML::Emitter& out) const {
  out << YAML::BeginMap << YAML::Key << "key_contours" << YAML::Value << YAML::BeginSeq;
  for (const KeyContour& k : scene.key_contours) {
    out << YAML::BeginMap << YAML::Key << "name" << YAML::Value << k.name << YAML::Key << "height_m" << YAML::Value
        << yaml_number(k.height_m);
    write_points(out, "points_m", k.polygon_m);
    out << YAML::EndMap;
  }
  out << YAML::EndSeq;
  FieldWriter writer(out);
  TerrainOptions options = scene.options;
  terrain_option_fields(writer, options);
  if (scene.elements) write_elements(out, *scene.elements);
  if (!scene.buildings.empty()) {
    out << YAML::Key << "buildings" << YAML::Value << YAML::BeginSeq;
    for (const BuildingFootprint& b : scene.buildings) {
      out << YAML::BeginMap << YAML::Key << "name" << YAML::Value << b.name;
      write_points(out, "footprint_m", b.polygon_m);
      out << YAML::Key << "storeys" << YAML::Value << b.storeys << YAML::Key << "storey_height_m" << YAML::Value
          << yaml_number(b.storey_height_m) << YAML::Key << "gap_m" << YAML::Value << yaml_number(b.gap_m)
          << YAML::Key << "bulk_density_kg_m3" << YAML::Value << yaml_number(b.bulk_density_kg_m3) << YAML::Key
          << "joint_break_force_n" << YAML::Value << yaml_number(b.joint_break_force_n) << YAML::EndMap;
    }
    out << YAML::EndSeq;
  }
  out << YAML::EndMap;
}

std::string TerrainSection::summary() const {
  return fmt::format("terrain: {} key contours, contours every {} m, slope {:.6g} deg, {} element layers, {} buildings",
                     scene.key_contours.size(), scene.options.contour_interval_m, scene.options.slope_rad / kRadPerDeg,
                     scene.elements ? scene.elements->layers.size() : 0, scene.buildings.size());
}

const TerrainSection& terrain_section(const Scene& scene) {
  const TerrainSection* section = scene.section<TerrainSection>();
  if (section == nullptr) throw InputError(fmt::format("{}: the scene has no 'terrain' section", scene.source_path));
  return *section;
}

SectionType terrain_section_type() {
  return {TerrainSection::kKey, "key contours, moving elements and buildings (models/terrain/terrain_section.h)",
          [](const YamlValue& value, const Scene& scene) -> std::shared_ptr<const SceneSection> {
            auto section = std::make_shared<TerrainSection>();
            section->scene = read_terrain_section(value);
            // the random bed follows the scene's seed (read before its sections)
            if (section->scene.elements) section->scene.elements->seed = scene.seed;
            return section;
          },
          false};
}

}  // namespace repose
