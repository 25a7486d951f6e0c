#include "models/terrain/terrain_section.h"

#include <filesystem>
#include <numbers>

#include "models/terrain/key_contour_file.h"

namespace repose {

namespace {

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
  const YamlMap m = value.map({"region_m", "gap_fraction", "layers"});
  ElementSource src;
  src.region_m = read_points(m.required("region_m", "a list of [x, y]"));
  src.gap_fraction = m.number_or("gap_fraction", Range::right_open(0.0, 1.0), src.gap_fraction);
  for (const YamlValue& item : m.required("layers", "a list of layers").list(1)) {
    const YamlMap l = item.map({"name", "radius_m", "rows", "friction", "restitution"});
    ElementLayer layer;
    layer.name = l.string_or("name", item.display_path());
    layer.radius_m = l.number("radius_m", Range::positive());
    layer.rows = static_cast<int>(l.integer_or("rows", IntRange{1, 1000}, layer.rows));
    layer.friction = l.number_or("friction", Range::non_negative(), layer.friction);
    layer.restitution = l.number_or("restitution", Range::closed(0.0, 1.0), layer.restitution);
    src.layers.push_back(layer);
  }
  return src;
}

BuildingFootprint read_building(const YamlValue& value) {
  const YamlMap m = value.map({"name", "footprint_m", "storeys", "storey_height_m", "gap_m"});
  BuildingFootprint b;
  b.name = m.string_or("name", value.display_path());
  b.polygon_m = read_points(m.required("footprint_m", "a list of [x, y]"));
  b.storeys = static_cast<int>(m.integer_or("storeys", IntRange{1, 1000}, b.storeys));
  b.storey_height_m = m.number_or("storey_height_m", Range::positive(), b.storey_height_m);
  b.gap_m = m.number_or("gap_m", Range::non_negative(), b.gap_m);
  return b;
}

}  // namespace

TerrainScene read_terrain_section(const YamlValue& section) {
  const YamlMap m = section.map({"key_contours", "key_contours_file", "contour_interval_m", "slope_deg",
                                 "smoothing_tolerance_m", "sample_spacing_m", "cell_size_m", "elements", "buildings"});
  TerrainScene scene;
  const std::optional<YamlValue> inline_contours = m.get("key_contours");
  const std::optional<YamlValue> contour_file = m.get("key_contours_file");
  if (inline_contours.has_value() == contour_file.has_value()) {
    m.fail_missing("key_contours", "exactly one of key_contours and key_contours_file");
  }
  if (inline_contours) {
    scene.key_contours = read_inline_contours(*inline_contours);
  } else {
    std::filesystem::path path(contour_file->string());
    if (path.is_relative()) path = std::filesystem::path(section.file()).parent_path() / path;
    scene.key_contours = read_key_contours(path.string());
  }
  TerrainOptions& o = scene.options;
  o.contour_interval_m = m.number_or("contour_interval_m", Range::positive(), o.contour_interval_m);
  o.slope_rad = m.number_or("slope_deg", Range::open(0.0, 90.0), o.slope_rad * 180.0 / std::numbers::pi) *
                std::numbers::pi / 180.0;
  o.smoothing_tolerance_m = m.number_or("smoothing_tolerance_m", Range::positive(), o.smoothing_tolerance_m);
  o.sample_spacing_m = m.number_or("sample_spacing_m", Range::positive(), o.sample_spacing_m);
  o.cell_size_m = m.number_or("cell_size_m", Range::positive(), o.cell_size_m);
  if (const auto e = m.get("elements")) scene.elements = read_elements(*e);
  if (const auto b = m.get("buildings")) {
    for (const YamlValue& item : b->list()) scene.buildings.push_back(read_building(item));
  }
  scene.validate();
  return scene;
}

}  // namespace repose
