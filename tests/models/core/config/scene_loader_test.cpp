#include "models/core/config/scene_loader.h"
#include "experiments/solvers/solver_registry.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <regex>
#include <utility>

#include "models/core/base/error.h"
#include "models/ground/ground_section.h"
#include "validation/particles/dem_section.h"

namespace repose {
namespace {

namespace fs = std::filesystem;
constexpr double kDeg = std::numbers::pi / 180.0;

const fs::path kScenes = fs::path(REPOSE_SOURCE_DIR) / "tests/data/scenes";

// The message load_scene throws for `path`, or "" when it loads.
std::string error_of(const std::string& path) {
  try {
    load_scene(path, solver_registry().sections());
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string error_of_text(const std::string& yaml) {
  try {
    load_scene_from_string(yaml, (kScenes / "good/inline.yaml").string(), solver_registry().sections());
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

Scene load_text(const std::string& yaml) { return load_scene_from_string(yaml, (kScenes / "good/inline.yaml").string(), solver_registry().sections()); }

std::vector<fs::path> yaml_files_in(const fs::path& dir) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().extension() == ".yaml") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// "# expect: KEY: FRAGMENT" on the first line of each malformed scene.
std::string expectation_of(const fs::path& file) {
  std::ifstream in(file);
  std::string first;
  std::getline(in, first);
  const std::string tag = "# expect: ";
  return first.rfind(tag, 0) == 0 ? first.substr(tag.size()) : "";
}

const std::string kGround = R"(
time: {step_s: 0.01, duration_s: 0.1}
ground:
  extent_m: [1, 1]
  cell_size_m: 0.1
  initial_height: {kind: flat, height_m: 0.01}
)";

TEST(SceneLoader, EveryMalformedSceneGivesItsOneLineMessage) {
  const auto files = yaml_files_in(kScenes / "bad");
  ASSERT_GE(files.size(), 20u);
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.string());
    const std::string expected = expectation_of(file);
    ASSERT_FALSE(expected.empty()) << "no '# expect: ' first line";
    const std::string message = error_of(file.string());
    ASSERT_FALSE(message.empty()) << "loaded without error";
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    const std::regex located("^" + std::regex_replace(file.string(), std::regex(R"([.^$|()\[\]{}*+?\\])"), R"(\$&)") +
                             R"(:[0-9]+:[0-9]+: )");
    EXPECT_TRUE(std::regex_search(message, located)) << message;
    EXPECT_NE(message.find(expected), std::string::npos) << message;
  }
}

TEST(SceneLoader, ErrorsPointAtTheOffendingLineAndColumn) {
  const fs::path bad = kScenes / "bad";
  // the value of the key
  EXPECT_EQ(error_of((bad / "negative_size.yaml").string()).rfind((bad / "negative_size.yaml").string() + ":5:16: ", 0), 0u);
  // an unknown key: the key itself
  EXPECT_EQ(error_of((bad / "unknown_key_nested.yaml").string()).rfind((bad / "unknown_key_nested.yaml").string() + ":5:3: ", 0), 0u);
  // a missing key: the map that lacks it (ground's first key)
  EXPECT_EQ(error_of((bad / "missing_required.yaml").string()).rfind((bad / "missing_required.yaml").string() + ":4:3: ", 0), 0u);
}

// YAML mistakes are reported where they are: the second document at its
// '---', an unterminated quote at the quote (not "missing key" further down).
TEST(SceneLoader, YamlMistakesPointAtTheirOwnLineAndColumn) {
  const fs::path bad = kScenes / "bad";
  for (const auto& [name, location] : {std::pair<std::string, std::string>{"yaml_second_document.yaml", ":7:1: yaml: "},
                                       {"yaml_unterminated_quote.yaml", ":2:7: name: "},
                                       {"yaml_unterminated_quote_paired.yaml", ":2:7: yaml: "}}) {
    const std::string file = (bad / name).string();
    EXPECT_EQ(error_of(file).rfind(file + location, 0), 0u) << error_of(file);
  }
}

TEST(SceneLoader, MissingSceneFileIsAnInputError) {
  EXPECT_THROW(load_scene((kScenes / "no_such_scene.yaml").string(), solver_registry().sections()), InputError);
  EXPECT_THROW(load_scene(kScenes.string(), solver_registry().sections()), InputError);
}

TEST(SceneLoader, EveryGoodSceneLoads) {
  const auto files = yaml_files_in(kScenes / "good");
  ASSERT_GE(files.size(), 4u);
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.string());
    const Scene s = load_scene(file.string(), solver_registry().sections());
    EXPECT_GT(s.time.step_count(), 0);
    EXPECT_GT(s.ground.grid.cell_count(), 0u);
    for (const ObjectSpec& o : s.objects) {
      EXPECT_TRUE(is_closed_manifold(o.body)) << o.name;
      EXPECT_GT(signed_volume_m3(o.body), 0.0) << o.name;
      EXPECT_FALSE(o.keyframes.empty());
    }
    EXPECT_FALSE(describe_scene(s).empty());
  }
}

TEST(SceneLoader, TheDefaultGroundSceneLoads) {
  const Scene s = load_scene(std::string(REPOSE_SOURCE_DIR) + "/experiments/scenes/default_ground.yaml", solver_registry().sections());
  EXPECT_EQ(s.ground.grid.nx, 256);
  EXPECT_EQ(s.ground.grid.ny, 256);
  EXPECT_EQ(s.time.step_count(), 60);  // 2 s at 30 fps
  ASSERT_EQ(s.objects.size(), 1u);
  EXPECT_GT(s.objects[0].keyframes.size(), 1u);
}

TEST(SceneLoader, DefaultsAreFilled) {
  const Scene s = load_scene((kScenes / "good/minimal.yaml").string(), solver_registry().sections());
  EXPECT_EQ(s.name, "minimal");
  EXPECT_EQ(s.seed, 0u);
  EXPECT_TRUE(fs::path(s.source_path).is_absolute());
  EXPECT_EQ(s.ground.grid.nx, 50);
  EXPECT_EQ(s.ground.grid.ny, 25);
  EXPECT_DOUBLE_EQ(s.ground.grid.cell_size_m, 0.01);
  // centred on the world origin
  EXPECT_DOUBLE_EQ(s.ground.grid.origin_x_m, -0.25);
  EXPECT_DOUBLE_EQ(s.ground.grid.origin_y_m, -0.125);
  EXPECT_EQ(s.ground.material, "sand");
  EXPECT_TRUE(s.ground.regions.empty());
  EXPECT_TRUE(s.objects.empty());
  EXPECT_FALSE(s.camera.has_value());
  EXPECT_EQ(dem_of(s), nullptr);
  // the ground model's section is read for every scene: its defaults
  ASSERT_NE(s.section<GroundModelSection>(), nullptr);
  const GroundModelSpec defaults;
  const GroundModelSpec& options = ground_model_section(s).options;
  EXPECT_EQ(options.sweep, defaults.sweep);
  EXPECT_EQ(options.substeps, defaults.substeps);
  EXPECT_EQ(options.coarse_factor, defaults.coarse_factor);
  EXPECT_EQ(options.collision, defaults.collision);
  EXPECT_EQ(s.time.step_count(), 10);
}

TEST(SceneLoader, PresetsHaveThePapersValues) {
  struct Expected {
    const char* name;
    double angle_deg, alpha;
  };
  for (const Expected& e : {Expected{"sand", 30, 1.0}, Expected{"mud", 60, 0.8}, Expected{"snow", 90, 0.0}}) {
    const Scene s = load_text(kGround + "  material: " + e.name + "\n");
    const Material m = ground_model_section(s).material(s.ground.material);
    EXPECT_EQ(m.name, e.name);
    EXPECT_NEAR(m.repose_angle_rad, e.angle_deg * kDeg, 1e-15);
    EXPECT_DOUBLE_EQ(m.alpha, e.alpha);
    EXPECT_DOUBLE_EQ(m.sigma, 0.2);
  }
}

TEST(SceneLoader, PresetFieldsCanBeOverridden) {
  const Scene s = load_text(kGround + "  material: clay\nground_model: {materials: {clay: {preset: mud, sigma: 0.1}}}\n");
  const Material m = ground_model_section(s).material("clay");
  EXPECT_EQ(m.name, "clay");
  EXPECT_DOUBLE_EQ(m.sigma, 0.1);
  EXPECT_DOUBLE_EQ(m.alpha, 0.8);
}

TEST(SceneLoader, ExplicitMaterialNeedsEveryParameter) {
  const std::string message =
      error_of_text(kGround + "  material: rock\nground_model: {materials: {rock: {alpha: 0.5, sigma: 0.2}}}\n");
  EXPECT_NE(message.find("ground_model.materials.rock.repose_angle_deg: expected a value for every parameter"),
            std::string::npos)
      << message;
}

TEST(SceneLoader, DegreesBecomeRadians) {
  const Scene s = load_scene((kScenes / "good/all_features.yaml").string(), solver_registry().sections());
  EXPECT_NEAR(ground_model_section(s).material(s.ground.regions[1].material).repose_angle_rad, 45 * kDeg, 1e-15);
  ASSERT_TRUE(s.camera.has_value());
  EXPECT_NEAR(s.camera->fov_y_rad, 50 * kDeg, 1e-15);
  EXPECT_NEAR(ground_model_section(s).options.max_substep_angle_rad, 2.5 * kDeg, 1e-15);
  // yaw 90 deg turns the crate's x axis onto y
  const Eigen::Vector3d x_turned = s.objects[0].keyframes[0].pose.orientation * Eigen::Vector3d::UnitX();
  EXPECT_NEAR((x_turned - Eigen::Vector3d::UnitY()).norm(), 0.0, 1e-12);
}

TEST(SceneLoader, OrientationIsYawAfterPitchAfterRoll) {
  // Rz(90) * Rx(90): z -> -y -> x, y -> z -> z; the other order would send z to -y
  const Eigen::Quaterniond q = orientation_from_rpy_deg({90, 0, 90});
  EXPECT_NEAR((q * Eigen::Vector3d::UnitZ() - Eigen::Vector3d::UnitX()).norm(), 0.0, 1e-12);
  EXPECT_NEAR((q * Eigen::Vector3d::UnitY() - Eigen::Vector3d::UnitZ()).norm(), 0.0, 1e-12);
  // pitch 90 sends z to x
  EXPECT_NEAR((orientation_from_rpy_deg({0, 90, 0}) * Eigen::Vector3d::UnitZ() - Eigen::Vector3d::UnitX()).norm(), 0.0,
              1e-12);
  for (const Eigen::Vector3d& rpy : {Eigen::Vector3d(10, 20, 30), Eigen::Vector3d(-170, 45, 120), Eigen::Vector3d(0, -80, -5)}) {
    EXPECT_NEAR((rpy_deg_from_orientation(orientation_from_rpy_deg(rpy)) - rpy).norm(), 0.0, 1e-9);
  }
}

TEST(SceneLoader, BodiesAreTessellatedAndScaled) {
  const Scene s = load_scene((kScenes / "good/all_features.yaml").string(), solver_registry().sections());
  ASSERT_EQ(s.objects.size(), 4u);
  const Aabb crate = bounding_box(s.objects[0].body);
  EXPECT_NEAR((crate.max - Eigen::Vector3d(0.1, 0.05, 0.05)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((crate.min + Eigen::Vector3d(0.1, 0.05, 0.05)).norm(), 0.0, 1e-15);
  EXPECT_TRUE(s.objects[1].simple);
  EXPECT_FALSE(s.objects[0].simple);
  // capsule scaled by 2: radius 0.06, straight part 0.2, total height 0.32
  const Aabb pill = bounding_box(s.objects[2].body);
  EXPECT_NEAR(pill.max.z() - pill.min.z(), 0.32, 1e-12);
  // the bucket: 0.28 m^3 scaled by 0.2 * 0.2 * 0.25
  EXPECT_EQ(s.objects[3].shape, ObjectSpec::Shape::kMesh);
  EXPECT_TRUE(fs::path(s.objects[3].mesh_path).is_absolute());
  EXPECT_NEAR(signed_volume_m3(s.objects[3].body), 0.28 * 0.2 * 0.2 * 0.25, 1e-12);
}

TEST(SceneLoader, ResolutionAndCellSizeGiveTheSameGrid) {
  const Scene a = load_text(R"(
time: {step_s: 0.01, duration_s: 0.1}
ground: {extent_m: [2, 1], resolution: [40, 20], origin_m: [0, 0], initial_height: {kind: flat, height_m: 0}})");
  const Scene b = load_text(R"(
time: {step_s: 0.01, duration_s: 0.1}
ground: {extent_m: [2, 1], cell_size_m: 0.05, origin_m: [0, 0], initial_height: {kind: flat, height_m: 0}})");
  EXPECT_EQ(a.ground.grid, b.ground.grid);
  const std::string message = error_of_text(R"(
time: {step_s: 0.01, duration_s: 0.1}
ground: {extent_m: [2, 1], resolution: [40, 40], initial_height: {kind: flat, height_m: 0}})");
  EXPECT_NE(message.find("ground.resolution: expected square cells"), std::string::npos) << message;
}

TEST(SceneLoader, ScaleMustBePositive) {
  const std::string message = error_of_text(kGround + R"(
objects:
  - {shape: sphere, radius_m: 0.1, scale: [1, -1, 1], motion: [{time_s: 0, position_m: [0, 0, 0]}]})");
  EXPECT_NE(message.find("objects[0].scale[1]: expected a finite number in (0, 1000000], got -1"), std::string::npos) << message;
}

TEST(PoseAt, InterpolatesAndHoldsAtTheEnds) {
  ObjectSpec o;
  Keyframe a, b;
  a.time_s = 1.0;
  a.pose.position_m = {0, 0, 1};
  b.time_s = 3.0;
  b.pose.position_m = {2, 4, 1};
  b.pose.orientation = orientation_from_rpy_deg({0, 0, 90});
  o.keyframes = {a, b};
  // held before the first and after the last keyframe
  EXPECT_EQ(o.pose_at(0.0).position_m, a.pose.position_m);
  EXPECT_EQ(o.pose_at(9.0).position_m, b.pose.position_m);
  EXPECT_NEAR(o.pose_at(9.0).orientation.angularDistance(b.pose.orientation), 0.0, 1e-12);
  // linear position, slerp orientation: halfway is 45 deg of yaw
  const Pose mid = o.pose_at(2.0);
  EXPECT_NEAR((mid.position_m - Eigen::Vector3d(1, 2, 1)).norm(), 0.0, 1e-15);
  EXPECT_NEAR(mid.orientation.angularDistance(orientation_from_rpy_deg({0, 0, 45})), 0.0, 1e-12);
  const Pose quarter = o.pose_at(1.5);
  EXPECT_NEAR(quarter.orientation.angularDistance(orientation_from_rpy_deg({0, 0, 22.5})), 0.0, 1e-12);
  EXPECT_NEAR((quarter.position_m - Eigen::Vector3d(0.5, 1, 1)).norm(), 0.0, 1e-15);
}

TEST(PoseAt, ASingleKeyframeIsStatic) {
  ObjectSpec o;
  Keyframe k;
  k.time_s = 0.5;
  k.pose.position_m = {1, 2, 3};
  o.keyframes = {k};
  for (double t : {0.0, 0.5, 100.0}) EXPECT_EQ(o.pose_at(t).position_m, k.pose.position_m);
}

TEST(TimeSpec, StepCountCoversTheDuration) {
  EXPECT_EQ((TimeSpec{1.0 / 30.0, 2.0}).step_count(), 60);
  EXPECT_EQ((TimeSpec{0.3, 1.0}).step_count(), 4);
  EXPECT_EQ((TimeSpec{0.1, 0.1}).step_count(), 1);
}

void expect_same_scene(const Scene& a, const Scene& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.seed, b.seed);
  EXPECT_EQ(a.time.step_s, b.time.step_s);
  EXPECT_EQ(a.time.duration_s, b.time.duration_s);
  EXPECT_EQ(a.ground.grid.nx, b.ground.grid.nx);
  EXPECT_EQ(a.ground.grid.ny, b.ground.grid.ny);
  EXPECT_NEAR(a.ground.grid.cell_size_m, b.ground.grid.cell_size_m, 1e-15);
  EXPECT_EQ(a.ground.grid.origin_x_m, b.ground.grid.origin_x_m);
  EXPECT_EQ(a.ground.initial.kind, b.ground.initial.kind);
  EXPECT_EQ(a.ground.initial.height_m, b.ground.initial.height_m);
  EXPECT_EQ(a.ground.initial.path, b.ground.initial.path);
  EXPECT_EQ(a.ground.material, b.ground.material);
  EXPECT_NEAR(ground_model_section(a).material(a.ground.material).repose_angle_rad,
              ground_model_section(b).material(b.ground.material).repose_angle_rad, 1e-15);
  ASSERT_EQ(a.ground.regions.size(), b.ground.regions.size());
  ASSERT_EQ(a.objects.size(), b.objects.size());
  for (std::size_t k = 0; k < a.objects.size(); ++k) {
    const ObjectSpec &x = a.objects[k], &y = b.objects[k];
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.shape, y.shape);
    EXPECT_EQ(x.body.F.rows(), y.body.F.rows());
    EXPECT_NEAR((x.body.V - y.body.V).cwiseAbs().maxCoeff(), 0.0, 1e-12);
    ASSERT_EQ(x.keyframes.size(), y.keyframes.size());
    for (std::size_t f = 0; f < x.keyframes.size(); ++f) {
      EXPECT_EQ(x.keyframes[f].time_s, y.keyframes[f].time_s);
      EXPECT_EQ(x.keyframes[f].pose.position_m, y.keyframes[f].pose.position_m);
      EXPECT_NEAR(x.keyframes[f].pose.orientation.angularDistance(y.keyframes[f].pose.orientation), 0.0, 1e-12);
    }
    ASSERT_EQ(x.dynamic.has_value(), y.dynamic.has_value());
    if (x.dynamic) {
      EXPECT_EQ(x.mass_kg(), y.mass_kg());
      EXPECT_EQ(x.dynamic->velocity_m_s, y.dynamic->velocity_m_s);
      EXPECT_EQ(x.dynamic->angular_velocity_rad_s, y.dynamic->angular_velocity_rad_s);
      EXPECT_EQ(x.dynamic->torque_n_m, y.dynamic->torque_n_m);
    }
  }
  EXPECT_EQ(a.camera.has_value(), b.camera.has_value());
  EXPECT_EQ(dem_of(a) != nullptr, dem_of(b) != nullptr);
  if (dem_of(a) && dem_of(b)) {
    EXPECT_EQ(dem_of(a)->rolling_model, dem_of(b)->rolling_model);
  }
  EXPECT_EQ(ground_model_section(a).options.collision, ground_model_section(b).options.collision);
  EXPECT_EQ(ground_model_section(a).options.substeps, ground_model_section(b).options.substeps);
  EXPECT_EQ(ground_model_section(a).materials.size(), ground_model_section(b).materials.size());
}

TEST(SceneLoader, TheResolvedSceneReadsBackToTheSameScene) {
  for (const fs::path& file : yaml_files_in(kScenes / "good")) {
    SCOPED_TRACE(file.string());
    const Scene s = load_scene(file.string(), solver_registry().sections());
    const std::string yaml = scene_to_yaml(s);
    // every default is written out
    EXPECT_NE(yaml.find("erosion_memory_steps"), std::string::npos);
    EXPECT_NE(yaml.find("ground_model"), std::string::npos);
    // written to another folder: paths inside are absolute, so they still resolve
    const Scene back = load_scene_from_string(yaml, (fs::temp_directory_path() / file.filename()).string(), solver_registry().sections());
    expect_same_scene(s, back);
  }
}

}  // namespace
}  // namespace repose
