#include "models/terrain/terrain_outputs.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <numbers>

#include "models/core/io/mesh_io.h"
#include "models/core/io/npy_io.h"
#include "tests/models/terrain/terrain_fixtures.h"
#include "tests/support/temp_dir.h"

namespace repose {
namespace {

namespace fs = std::filesystem;

TEST(TerrainOutputs, WritesMeshContoursAndHeightsThatReadBack) {
  const test_support::TempDir temp;
  const fs::path& dir = temp.path;
  TerrainOptions o;
  o.slope_rad = 25.0 * std::numbers::pi / 180.0;
  o.sample_spacing_m = 2.0;
  const Terrain t = build_terrain({{"foot", test::rectangle_polygon(0, 0, 40, 20), 5.0}}, o);
  const std::vector<PlacedElement> elements = {{Eigen::Vector3d(1, 2, 3), 0.5, 0}};
  const auto written = write_terrain_outputs(dir.string(), t, elements, {});
  EXPECT_EQ(written.size(), 6u);  // no buildings.obj

  const TriangleMesh back = read_mesh((dir / "terrain_mesh.obj").string());
  EXPECT_EQ(back.V, t.mesh.V);  // OBJ is round-trip exact
  EXPECT_EQ(back.F, t.mesh.F);
  const ArrayXXdR contours = read_npy_2d((dir / "contours.npy").string());
  std::size_t points = 0;
  for (const TerrainContour& c : t.contours.contours) points += c.polygon_m.size();
  EXPECT_EQ(static_cast<std::size_t>(contours.rows()), points);
  EXPECT_EQ(contours(0, 3), 5.0);  // the key contour comes first, at its height
  EXPECT_EQ(read_npy_2d((dir / "terrain_height.npy").string()).cols(), t.height_field.nx());
  EXPECT_EQ(read_npy_2d((dir / "elements.npy").string())(0, 3), 0.5);
}

}  // namespace
}  // namespace repose
