#include "models/terrain/key_contour_file.h"

#include <gtest/gtest.h>

#include "models/core/base/error.h"

namespace repose {
namespace {

std::string error_of(const std::string& text) {
  try {
    parse_key_contours(text, "hills.geojson");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(KeyContourFile, ReadsFeaturesAndDropsTheClosingPoint) {
  const auto cs = parse_key_contours(R"({"type": "FeatureCollection", "features": [
    {"type": "Feature", "properties": {"name": "foot", "height_m": 100},
     "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [10, 0], [10, 10], [0, 10], [0, 0]]]}},
    {"type": "Feature", "properties": {"height_m": 120.5},
     "geometry": {"type": "Polygon", "coordinates": [[[2, 2], [4, 2], [3, 4]]]}}]})",
                                     "hills.geojson");
  ASSERT_EQ(cs.size(), 2u);
  EXPECT_EQ(cs[0].name, "foot");
  EXPECT_EQ(cs[0].polygon_m.size(), 4u);
  EXPECT_DOUBLE_EQ(cs[0].height_m, 100.0);
  EXPECT_DOUBLE_EQ(cs[1].height_m, 120.5);
  EXPECT_EQ(cs[1].polygon_m[2], Point2(3, 4));
  EXPECT_EQ(cs[1].name, "hills.geojson: features[1]");  // no name: where it is
}

TEST(KeyContourFile, ErrorsNameTheFileAndTheFeature) {
  EXPECT_NE(error_of("{").find("hills.geojson: not JSON"), std::string::npos);
  EXPECT_NE(error_of(R"({"type": "Feature"})").find("FeatureCollection"), std::string::npos);
  const std::string no_height = error_of(R"({"type": "FeatureCollection", "features": [
    {"type": "Feature", "properties": {"name": "a"}, "geometry": {"type": "Polygon", "coordinates": [[[0,0],[1,0],[0,1]]]}}]})");
  EXPECT_NE(no_height.find("features[0]: properties.height_m"), std::string::npos) << no_height;
  const std::string holes = error_of(R"({"type": "FeatureCollection", "features": [
    {"type": "Feature", "properties": {"name": "ring", "height_m": 1},
     "geometry": {"type": "Polygon", "coordinates": [[[0,0],[9,0],[0,9]], [[1,1],[2,1],[1,2]]]}}]})");
  EXPECT_NE(holes.find("('ring'): polygons with holes"), std::string::npos) << holes;
  const std::string line = error_of(R"({"type": "FeatureCollection", "features": [
    {"type": "Feature", "properties": {"name": "l", "height_m": 1}, "geometry": {"type": "LineString", "coordinates": []}}]})");
  EXPECT_NE(line.find("geometry.type must be \"Polygon\""), std::string::npos) << line;
}

TEST(KeyContourFile, MissingFileIsAnInputError) {
  EXPECT_THROW(read_key_contours("/nonexistent/hills.geojson"), InputError);
}

}  // namespace
}  // namespace repose
