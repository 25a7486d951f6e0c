#include "validation/rigid/debris_solver.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <numbers>

#include "models/core/base/error.h"
#include "models/core/config/scene.h"
#include "models/terrain/terrain_section.h"
#include "tests/support/temp_dir.h"

namespace repose {
namespace {

// Nothing moves: the elements and parts stay where the spec put them.
class StillWorld final : public DebrisWorld {
 public:
  explicit StillWorld(const DebrisWorldSpec& spec) : spec_(spec) {}
  void step() override {}
  double time_step_s() const override { return 0.05; }
  GrainSet elements() const override {
    GrainSet g;
    g.position_m.resize(static_cast<Eigen::Index>(spec_.elements.size()), 3);
    g.radius_m.resize(g.position_m.rows());
    g.velocity_m_s = MatrixX3dR::Zero(g.position_m.rows(), 3);
    for (std::size_t i = 0; i < spec_.elements.size(); ++i) {
      g.position_m.row(static_cast<Eigen::Index>(i)) = spec_.elements[i].centre_m.transpose();
      g.radius_m(static_cast<Eigen::Index>(i)) = spec_.elements[i].radius_m;
    }
    return g;
  }
  std::vector<Pose> part_poses() const override {
    std::vector<Pose> out;
    for (const DebrisPart& p : spec_.parts) out.push_back({p.centre_m, Eigen::Quaterniond::Identity()});
    return out;
  }
  std::vector<bool> joints_broken() const override { return std::vector<bool>(spec_.joints.size(), false); }
  std::vector<double> joint_forces_n() const override { return std::vector<double>(spec_.joints.size(), 0.0); }
  std::vector<Eigen::Vector3d> part_element_forces_n() const override {
    return std::vector<Eigen::Vector3d>(spec_.parts.size(), Eigen::Vector3d::Zero());
  }

 private:
  DebrisWorldSpec spec_;
};

RigidEngine still_engine() {
  RigidEngine e;
  e.name = "still";
  e.version = "test";
  e.make_debris_world = [](const DebrisWorldSpec& spec) { return std::make_unique<StillWorld>(spec); };
  return e;
}

Scene terrain_scene(bool with_elements) {
  TerrainScene t;
  t.key_contours = {{"valley", {{-40, -40}, {40, -40}, {40, 40}, {-40, 40}}, 0.0}};
  t.options.slope_rad = 20.0 * std::numbers::pi / 180.0;
  t.options.contour_interval_m = 2.0;
  t.options.sample_spacing_m = 2.0;
  if (with_elements) {
    ElementSource e;
    e.region_m = {{-5, 10}, {5, 10}, {5, 15}, {-5, 15}};
    e.layers = {{"rock", 0.5, 1}};
    t.elements = e;
  }
  t.buildings = {{"shed", {{-4, 25}, {4, 25}, {4, 30}, {-4, 30}}, 1, 3.0, 0.02}};
  Scene s;
  s.ground.grid = Grid{40, 40, 2.0, -40.0, -40.0};
  s.time.duration_s = 0.5;
  auto section = std::make_shared<TerrainSection>();
  section->scene = t;
  s.sections[TerrainSection::kKey] = section;
  return s;
}

TEST(DebrisSolver, AStillWorldReportsNoRunoutNoDamageAndItsFiles) {
  const auto compiled = compile_debris(terrain_scene(true), still_engine());
  const test_support::TempDir temp;
  const std::filesystem::path& dir = temp.path;
  RunOptions options;
  options.output_dir = dir.string();
  const repose::Run run = compiled->run(compiled->default_values(), options);
  EXPECT_GT(run.measure("element_count").value, 10.0);
  EXPECT_EQ(run.measure("steps").value, 10.0);
  EXPECT_EQ(run.measure("runout_m").value, 0.0);
  EXPECT_EQ(run.measure("joints_broken").value, 0.0);
  EXPECT_EQ(run.measure("building.shed.parts_moved").value, 0.0);
  EXPECT_EQ(run.measure("building.shed.joints").value, 1.0);  // one part, fixed to the ground
  EXPECT_TRUE((run.field("height_final").heights() == run.field("height_initial").heights()).all());
  EXPECT_GT(run.field("deposit").volume_m3(), 0.0);
  for (const std::string& f : run.files) EXPECT_TRUE(std::filesystem::exists(dir / f)) << f;
}

TEST(DebrisSolver, ATerrainWithoutElementsIsRefusedNamingTheKey) {
  try {
    compile_debris(terrain_scene(false), still_engine());
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("terrain: elements"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace repose
