// Real LIGGGHTS runs (skipped where it is not installed) of the run script
// for a box that turns and translates between keyframes: the mesh, read
// back with `dump mesh/stl` at every keyframe, lies where ObjectSpec::pose_at
// puts the object. This checks how LIGGGHTS superposes the run script's
// `fix move/mesh linear` and `rotate` fixes (the rotation's origin moving
// with the linear motion; a new pair per segment), and that a mesh reaching
// beyond the grid keeps every element. No bed: a one-grain
// restart stands in for the settled bed, so the run takes about a second.

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "models/core/io/mesh_io.h"
#include "tests/validation/liggghts/dem_test_scene.h"
#include "validation/liggghts/liggghts_runner.h"
#include "validation/liggghts/liggghts_script.h"

#include "tests/support/liggghts_test.h"

namespace repose {
namespace {

namespace fs = std::filesystem;

std::vector<Eigen::Vector3d> stl_ascii_vertices(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  const std::regex vertex(R"(vertex\s+(\S+)\s+(\S+)\s+(\S+))");
  std::vector<Eigen::Vector3d> out;
  for (auto it = std::sregex_iterator(s.begin(), s.end(), vertex); it != std::sregex_iterator(); ++it) {
    out.emplace_back(std::stod((*it)[1]), std::stod((*it)[2]), std::stod((*it)[3]));
  }
  return out;
}

// The largest distance from a point of one set to the nearest of the other, both ways.
double set_distance(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b) {
  const auto one_way = [](const auto& p, const auto& q) {
    double worst = 0.0;
    for (const auto& x : p) {
      double best = std::numeric_limits<double>::infinity();
      for (const auto& y : q) best = std::min(best, (x - y).norm());
      worst = std::max(worst, best);
    }
    return worst;
  };
  return std::max(one_way(a, b), one_way(b, a));
}

// A one-grain "bed" (its restart file) in dir, on the small scene's 4 x 4 cm grid.
void write_one_grain_bed(const fs::path& dir, const DemSpec& dem) {
  std::ofstream(dir / "bed.in") << fmt::format(
      "atom_style granular\natom_modify map array\nboundary f f f\nnewton off\ncommunicate single vel yes\n"
      "units si\nregion domain block 0 0.04 0 0.04 0 0.02 units box\ncreate_box {} domain\n"
      "create_atoms 1 single 0.004 0.004 0.002 units box\nset atom 1 diameter 0.004 density 2500\n"
      "write_restart {}\nprint \"{}\"\n",
      dem.floor == DemSpec::Floor::kRough ? 2 : 1, kBedRestartFile, kCompleteMarker);
  LiggghtsRunOptions options;
  options.wall_clock_limit_s = 20;
  run_liggghts(dir.string(), "bed.in", options);
}

// The script with the mesh obj0 dumped every `every` steps into meshes/, run in dir.
void run_with_mesh_dumps(const fs::path& dir, RunScript script, long every) {
  const std::size_t first_segment = script.text.find("# segment 0");
  ASSERT_NE(first_segment, std::string::npos);
  script.text.insert(first_segment, fmt::format("dump meshes all mesh/stl {} meshes/mesh_*.stl obj0\n", every));
  for (const LiggghtsMeshFile& m : script.meshes) write_stl((dir / m.file_name).string(), m.mesh);
  fs::create_directories(dir / kDumpDirectory);
  fs::create_directories(dir / "meshes");
  std::ofstream(dir / "run.in") << script.text;
  LiggghtsRunOptions options;
  options.wall_clock_limit_s = 20;
  options.total_steps = script.total_steps;
  options.dump_directory = kDumpDirectory;
  run_liggghts(dir.string(), "run.in", options);
}

class RotatingMesh : public test_support::LiggghtsTest {};

// LIGGGHTS deletes the mesh elements whose centre lies outside the box
// ("Mesh (id obj0): N mesh elements have been lost / left the domain"): a
// bucket scooping at the ground's edge, or tipped out over it, must keep
// every element. Here a paddle straddles the grid's y edge from the start
// and turns out beyond its x edge; the box grows to hold it while the walls
// stay on the grid's edges.
TEST_F(RotatingMesh, AMeshReachingBeyondTheGridKeepsEveryElement) {
  Scene scene = testing::small_dem_scene(false);
  scene.time.duration_s = 0.02;
  ObjectSpec paddle;
  paddle.name = "paddle";
  paddle.shape = ObjectSpec::Shape::kBox;
  paddle.half_extents_m = Eigen::Vector3d(0.008, 0.004, 0.003);
  paddle.body = make_box(paddle.half_extents_m);
  const Eigen::Quaterniond tipped(Eigen::AngleAxisd(3 * std::numbers::pi / 4, Eigen::Vector3d::UnitY()));
  paddle.keyframes = {{0.0, Pose{Eigen::Vector3d(0.02, 0.04, 0.03), Eigen::Quaterniond::Identity()}},
                      {0.02, Pose{Eigen::Vector3d(0.038, 0.04, 0.03), tipped}}};
  scene.objects.push_back(paddle);
  const DemSpec& dem = *dem_of(scene);
  write_one_grain_bed(dir_, dem);
  const RunScript script = run_script(scene);
  // the walls stay on the grid, the box holds the paddle's whole motion
  EXPECT_EQ(script.domain.y_max_m, 0.04);
  EXPECT_EQ(script.domain.x_max_m, 0.04);
  EXPECT_GE(script.box.y_max_m, 0.04 + paddle.half_extents_m.norm());
  EXPECT_GE(script.box.x_max_m, 0.038 + paddle.half_extents_m.norm());
  EXPECT_NE(script.text.find("fix wall_ymax all wall/gran"), std::string::npos);
  EXPECT_NE(script.text.find("yplane 0.04\n"), std::string::npos) << script.text;
  const long every = std::lround(0.01 / dem.time_step_s);
  ASSERT_NO_THROW(run_with_mesh_dumps(dir_, script, every));
  for (int k = 0; k <= 2; ++k) {
    const fs::path dumped = dir_ / "meshes" / fmt::format("mesh_{}.stl", k * every);
    ASSERT_TRUE(fs::exists(dumped)) << dumped;
    EXPECT_EQ(stl_ascii_vertices(dumped).size(), static_cast<std::size_t>(3 * paddle.body.F.rows())) << dumped;
  }
}

TEST_F(RotatingMesh, MeshEndsEachSegmentAtTheKeyframedPose) {
  Scene scene = testing::small_dem_scene(false);
  scene.time.duration_s = 0.02;
  ObjectSpec paddle;
  paddle.name = "paddle";
  paddle.shape = ObjectSpec::Shape::kBox;
  paddle.half_extents_m = Eigen::Vector3d(0.008, 0.004, 0.003);
  paddle.body = make_box(paddle.half_extents_m);
  const Eigen::Quaterniond quarter_z(Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitZ()));
  const Eigen::Quaterniond then_x(Eigen::AngleAxisd(std::numbers::pi / 3, Eigen::Vector3d::UnitX()) * quarter_z);
  // turns 90 degrees about z while moving, then 60 degrees about (world) x while moving back
  paddle.keyframes = {{0.0, Pose{Eigen::Vector3d(0.02, 0.02, 0.03), Eigen::Quaterniond::Identity()}},
                      {0.01, Pose{Eigen::Vector3d(0.023, 0.018, 0.032), quarter_z}},
                      {0.02, Pose{Eigen::Vector3d(0.019, 0.021, 0.029), then_x}}};
  scene.objects.push_back(paddle);

  const DemSpec& dem = *dem_of(scene);
  write_one_grain_bed(dir_, dem);
  ASSERT_TRUE(fs::exists(dir_ / kBedRestartFile));

  const RunScript script = run_script(scene);
  ASSERT_EQ(script.meshes.size(), 1u);
  ASSERT_NE(script.text.find("rotate origin"), std::string::npos) << script.text;
  // the mesh dumped at each keyframe (steps 0, 1000, 2000)
  const long every = std::lround(0.01 / dem.time_step_s);
  run_with_mesh_dumps(dir_, script, every);

  for (int k = 0; k <= 2; ++k) {
    const fs::path dumped = dir_ / "meshes" / fmt::format("mesh_{}.stl", k * every);
    ASSERT_TRUE(fs::exists(dumped)) << dumped;
    const std::vector<Eigen::Vector3d> got = stl_ascii_vertices(dumped);
    const TriangleMesh expected = transformed(paddle.body, scene.objects[0].pose_at(0.01 * k));
    std::vector<Eigen::Vector3d> want;
    for (Eigen::Index v = 0; v < expected.V.rows(); ++v) want.push_back(expected.V.row(v).transpose());
    ASSERT_EQ(got.size(), static_cast<std::size_t>(3 * expected.F.rows())) << dumped;
    // within a micrometre (the box is 16 mm long; a wrong turn or origin is off by millimetres)
    EXPECT_LT(set_distance(got, want), 1e-6) << "keyframe " << k;
  }
}

}  // namespace
}  // namespace repose
