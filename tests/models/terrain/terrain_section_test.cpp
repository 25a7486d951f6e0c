#include "models/terrain/terrain_section.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <numbers>

#include "models/core/base/error.h"
#include "tests/support/temp_dir.h"

namespace repose {
namespace {

namespace fs = std::filesystem;

TerrainScene read(const std::string& text, const std::string& file = "scene.yaml") {
  const YamlValue root = parse_yaml(text, file);
  return read_terrain_section(root.map({"terrain"}).required("terrain", "a terrain section"));
}

std::string error_of(const std::string& text) {
  try {
    read(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

const char* kSquare = "[[0, 0], [100, 0], [100, 100], [0, 100]]";

TEST(TerrainSection, ReadsContoursOptionsElementsAndBuildings) {
  const TerrainScene s = read(std::string(R"(
terrain:
  key_contours:
    - {name: foot, height_m: 5, points_m: )") + kSquare + R"(}
  slope_deg: 20
  contour_interval_m: 2.5
  elements:
    region_m: [[10, 10], [30, 10], [30, 30]]
    layers: [{name: bed, radius_m: 0.5, rows: 2, friction: 0.7, restitution: 0.1}]
  buildings:
    - {name: house, footprint_m: [[60, 60], [70, 60], [70, 70], [60, 70]], storeys: 2}
)");
  ASSERT_EQ(s.key_contours.size(), 1u);
  EXPECT_EQ(s.key_contours[0].name, "foot");
  EXPECT_DOUBLE_EQ(s.key_contours[0].height_m, 5.0);
  EXPECT_NEAR(s.options.slope_rad, 20.0 * std::numbers::pi / 180.0, 1e-15);
  EXPECT_DOUBLE_EQ(s.options.contour_interval_m, 2.5);
  EXPECT_DOUBLE_EQ(s.options.sample_spacing_m, TerrainOptions().sample_spacing_m);  // default
  ASSERT_TRUE(s.elements.has_value());
  EXPECT_EQ(s.elements->layers[0].rows, 2);
  EXPECT_DOUBLE_EQ(s.elements->layers[0].friction, 0.7);
  ASSERT_EQ(s.buildings.size(), 1u);
  EXPECT_EQ(s.buildings[0].storeys, 2);
}

TEST(TerrainSection, ReadsARandomBedsSpreadAndJitter) {
  const TerrainScene s = read(std::string("terrain:\n  key_contours: [{height_m: 0, points_m: ") + kSquare + R"(}]
  elements:
    region_m: [[10, 10], [30, 10], [30, 30]]
    radius_spread: 0.25
    position_jitter: 0.5
    layers: [{radius_m: 0.5}]
)");
  ASSERT_TRUE(s.elements.has_value());
  EXPECT_DOUBLE_EQ(s.elements->radius_spread, 0.25);
  EXPECT_DOUBLE_EQ(s.elements->position_jitter, 0.5);
  const std::string bad = error_of(std::string("terrain:\n  key_contours: [{height_m: 0, points_m: ") + kSquare +
                                   "}]\n  elements: {region_m: [[10, 10], [30, 10], [30, 30]], radius_spread: 1, "
                                   "layers: [{radius_m: 0.5}]}\n");
  EXPECT_NE(bad.find("radius_spread"), std::string::npos) << bad;
}

TEST(TerrainSection, ErrorsNameTheKey) {
  const std::string unknown = error_of(std::string("terrain:\n  slope: 3\n  key_contours: [{height_m: 0, points_m: ") +
                                       kSquare + "}]\n");
  EXPECT_NE(unknown.find("slope"), std::string::npos) << unknown;
  const std::string neither = error_of("terrain:\n  slope_deg: 30\n");
  EXPECT_NE(neither.find("exactly one of key_contours and key_contours_file"), std::string::npos) << neither;
  const std::string steep = error_of(std::string("terrain:\n  slope_deg: 90\n  key_contours: [{height_m: 0, points_m: ") +
                                     kSquare + "}]\n");
  EXPECT_NE(steep.find("terrain.slope_deg"), std::string::npos) << steep;
  const std::string restitution = error_of(std::string("terrain:\n  key_contours: [{height_m: 0, points_m: ") + kSquare +
                                           "}]\n  elements: {region_m: [[1,1],[2,1],[2,2]], layers: [{radius_m: 1, "
                                           "restitution: 2}]}\n");
  EXPECT_NE(restitution.find("restitution"), std::string::npos) << restitution;
}

TEST(TerrainSection, ReadsTheRigidEnginesValuesOfLayersAndBuildings) {
  const TerrainScene s = read(std::string("terrain:\n  key_contours: [{height_m: 0, points_m: ") + kSquare + R"(}]
  elements:
    region_m: [[10, 10], [30, 10], [30, 30]]
    layers: [{radius_m: 0.5, density_kg_m3: 2000, rolling_friction: 0.3}]
  buildings:
    - {name: house, footprint_m: [[60, 60], [70, 60], [70, 70], [60, 70]], bulk_density_kg_m3: 250, joint_break_force_n: 3.0e6}
)");
  EXPECT_DOUBLE_EQ(s.elements->layers[0].density_kg_m3, 2000.0);
  EXPECT_DOUBLE_EQ(s.elements->layers[0].rolling_friction, 0.3);
  EXPECT_DOUBLE_EQ(s.buildings[0].bulk_density_kg_m3, 250.0);
  EXPECT_DOUBLE_EQ(s.buildings[0].joint_break_force_n, 3.0e6);
  const std::string joint = error_of(std::string("terrain:\n  key_contours: [{height_m: 0, points_m: ") + kSquare +
                                     "}]\n  buildings: [{footprint_m: [[60,60],[70,60],[70,70]], joint_break_force_n: 0}]\n");
  EXPECT_NE(joint.find("joint_break_force_n"), std::string::npos) << joint;
  const std::string density = error_of(std::string("terrain:\n  key_contours: [{height_m: 0, points_m: ") + kSquare +
                                       "}]\n  elements: {region_m: [[1,1],[2,1],[2,2]], layers: [{radius_m: 1, "
                                       "density_kg_m3: -5}]}\n");
  EXPECT_NE(density.find("density_kg_m3"), std::string::npos) << density;
}

TEST(TerrainSection, ContourFileIsTakenFromTheScenesFolder) {
  const test_support::TempDir temp;
  const fs::path& dir = temp.path;
  std::ofstream(dir / "hills.geojson") << R"({"type": "FeatureCollection", "features": [
    {"type": "Feature", "properties": {"name": "foot", "height_m": 3},
     "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [10, 0], [10, 10], [0, 10], [0, 0]]]}}]})";
  const TerrainScene s = read("terrain:\n  key_contours_file: hills.geojson\n", (dir / "scene.yaml").string());
  ASSERT_EQ(s.key_contours.size(), 1u);
  EXPECT_EQ(s.key_contours[0].name, "foot");
}

}  // namespace
}  // namespace repose
