#include "validation/liggghts_debris/liggghts_debris_solver.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

#include <gtest/gtest.h>

#include "experiments/solvers/solver_registry.h"
#include "models/core/config/scene_loader.h"
#include "models/core/io/npy_io.h"
#include "tests/support/temp_dir.h"

namespace repose {
namespace {

Scene shipped(const std::string& name) {
  const auto path = std::filesystem::path(REPOSE_SOURCE_DIR) / "experiments" / "scenes" / name;
  return load_scene(path.string(), solver_registry().sections());
}

// The shipped scene with another duration (s, as written in YAML).
Scene load_scene_with_duration(const std::filesystem::path& path, const std::string& duration_s) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  std::string yaml = text.str();
  const std::string from = "duration_s: 8.0";
  const std::size_t at = yaml.find(from);
  if (at == std::string::npos) throw std::runtime_error(path.string() + " has no '" + from + "'");
  yaml.replace(at, from.size(), "duration_s: " + duration_s);
  return load_scene_from_string(yaml, path.string(), solver_registry().sections());
}

TEST(LiggghtsDebrisSolver, RunsATerrainScenesDebrisAndStillADemScene) {
  const LiggghtsDebrisSolver solver;
  EXPECT_EQ(solver.name(), "liggghts");
  std::string why;
  for (const char* scene : {"terrain_debris.yaml", "dem_indent.yaml"}) {
    SCOPED_TRACE(scene);
    const Scene s = shipped(scene);
    ASSERT_TRUE(solver.can_run(s, &why)) << why;
    EXPECT_NE(solver.compile(s), nullptr);
  }
}

// The collapse series the experiment draws for LIGGGHTS (plots/terrain_debris.py,
// as for Bullet and ODE): frames every duration / 20 and at the end, each
// with every element (x y z r) and every part's pose, the last one where the
// elements ended. A 0.2 s run of the shipped scene.
TEST(LiggghtsDebrisSolver, WritesTheFrameSeriesItPromises) {
  const auto path = std::filesystem::path(REPOSE_SOURCE_DIR) / "experiments" / "scenes" / "terrain_debris.yaml";
  const Scene scene = load_scene_with_duration(path, "0.2");
  const test_support::TempDir temp;
  const std::filesystem::path& dir = temp.path;
  const auto compiled = LiggghtsDebrisSolver().compile(scene);
  RunOptions options;
  options.output_dir = dir.string();
  const repose::Run run = compiled->run(compiled->default_values(), options);
  const auto elements = static_cast<Eigen::Index>(run.measure("element_count").value);
  const auto parts = static_cast<Eigen::Index>(run.measure("part_count").value);
  ASSERT_GT(elements, 700);
  for (int k = 0; k <= 20; ++k) {
    SCOPED_TRACE(k);
    const ArrayXXdR e = read_npy_2d((dir / fmt::format("frames/elements_{:03d}.npy", k)).string());
    ASSERT_EQ(e.rows(), elements);
    ASSERT_EQ(e.cols(), 4);
    const ArrayXXdR p = read_npy_2d((dir / fmt::format("frames/parts_{:03d}.npy", k)).string());
    EXPECT_EQ(p.size(), 7 * parts);
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "frames/elements_021.npy"));
  std::ifstream front(dir / "front.csv");
  std::string line;
  int rows = 0;
  while (std::getline(front, line)) ++rows;
  EXPECT_EQ(rows, 1 + 21);  // a header and a row per frame
}

TEST(LiggghtsDebrisSolver, ASceneWithNeitherSectionIsRefusedSayingWhy) {
  const LiggghtsDebrisSolver solver;
  const Scene s = load_scene_from_string(
      "name: bare\ntime: {step_s: 0.1, duration_s: 1}\n"
      "ground: {extent_m: [1, 1], cell_size_m: 0.1, initial_height: {kind: flat, height_m: 0}, material: sand}\n",
      "bare.yaml", solver_registry().sections());
  std::string why;
  EXPECT_FALSE(solver.can_run(s, &why));
  EXPECT_NE(why.find("terrain"), std::string::npos) << why;
}

}  // namespace
}  // namespace repose
