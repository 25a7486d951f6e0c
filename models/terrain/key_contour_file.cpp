#include "models/terrain/key_contour_file.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "models/core/base/error.h"
#include "models/core/io/input_file.h"

namespace repose {

namespace {

using Json = nlohmann::json;

Polygon2 read_ring(const Json& ring, const std::string& where) {
  if (!ring.is_array()) throw InputError(fmt::format("{}: a ring must be an array of [x, y] points", where));
  Polygon2 polygon;
  for (const Json& point : ring) {
    if (!point.is_array() || point.size() < 2 || !point[0].is_number() || !point[1].is_number()) {
      throw InputError(fmt::format("{}: every point must be [x, y] numbers", where));
    }
    polygon.emplace_back(point[0].get<double>(), point[1].get<double>());
  }
  if (polygon.size() > 1 && polygon.front() == polygon.back()) polygon.pop_back();
  return polygon;
}

KeyContour read_feature(const Json& feature, const std::string& where) {
  if (!feature.is_object()) throw InputError(fmt::format("{}: must be an object", where));
  const Json& props = feature.value("properties", Json::object());
  if (!props.contains("height_m") || !props["height_m"].is_number()) {
    throw InputError(fmt::format("{}: properties.height_m (a number) is required", where));
  }
  KeyContour contour;
  contour.name = props.contains("name") && props["name"].is_string() ? props["name"].get<std::string>() : where;
  contour.height_m = props["height_m"].get<double>();
  const Json& geometry = feature.value("geometry", Json::object());
  if (geometry.value("type", std::string()) != "Polygon") {
    throw InputError(fmt::format("{} ('{}'): geometry.type must be \"Polygon\"", where, contour.name));
  }
  const Json& rings = geometry.value("coordinates", Json::array());
  if (!rings.is_array() || rings.empty()) {
    throw InputError(fmt::format("{} ('{}'): geometry.coordinates needs one ring", where, contour.name));
  }
  if (rings.size() > 1) {
    throw InputError(fmt::format("{} ('{}'): polygons with holes are not key contours; give each inner ring as "
                                 "its own feature with its own height_m",
                                 where, contour.name));
  }
  contour.polygon_m = read_ring(rings[0], fmt::format("{} ('{}')", where, contour.name));
  return contour;
}

}  // namespace

std::vector<KeyContour> parse_key_contours(const std::string& text, const std::string& source) {
  Json doc;
  try {
    doc = Json::parse(text);
  } catch (const Json::parse_error& e) {
    throw InputError(fmt::format("{}: not JSON: {}", source, e.what()));
  }
  if (!doc.is_object() || doc.value("type", std::string()) != "FeatureCollection" || !doc.contains("features") ||
      !doc["features"].is_array()) {
    throw InputError(fmt::format("{}: expected a GeoJSON FeatureCollection with a features array", source));
  }
  std::vector<KeyContour> contours;
  for (std::size_t i = 0; i < doc["features"].size(); ++i) {
    contours.push_back(read_feature(doc["features"][i], fmt::format("{}: features[{}]", source, i)));
  }
  return contours;
}

std::vector<KeyContour> read_key_contours(const std::string& path) {
  require_regular_file(path, "GeoJSON key contour");
  const std::uintmax_t bytes = std::filesystem::file_size(path);
  if (bytes > kMaxKeyContourFileBytes) {
    throw InputError(fmt::format("{}: {} bytes, more than the {} a key contour file may hold", path, bytes,
                                 kMaxKeyContourFileBytes));
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(fmt::format("{}: cannot be read", path));
  std::ostringstream text;
  text << in.rdbuf();
  return parse_key_contours(text.str(), path);
}

}  // namespace repose
