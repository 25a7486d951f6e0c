#include "validation/liggghts/liggghts_script.h"
#include "validation/particles/dem_section.h"

#include <cmath>
#include <numbers>
#include <regex>
#include <sstream>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "tests/validation/liggghts/dem_test_scene.h"

namespace repose {
namespace {

std::string message_of_refused_step(double step_s, DemSpec dem) {
  dem.time_step_s = step_s;
  try {
    validate(dem);
  } catch (const InputError& e) {
    return e.what();
  }
  return {};
}

TEST(LiggghtsScript, RayleighTimeMatchesTheFormula) {
  DemSpec dem;
  dem.grain_radius_m = 0.002;
  dem.radius_spread = 0.0;
  dem.youngs_modulus_pa = 5e6;
  dem.poisson_ratio = 0.3;
  dem.density_kg_m3 = 2500;
  const double g = 5e6 / (2 * 1.3);
  EXPECT_NEAR(rayleigh_time_s(dem), std::numbers::pi * 0.002 * std::sqrt(2500 / g) / (0.1631 * 0.3 + 0.8766), 1e-15);
  // the smallest grain sets it
  dem.radius_spread = 0.25;
  EXPECT_NEAR(rayleigh_time_s(dem), 0.75 * std::numbers::pi * 0.002 * std::sqrt(2500 / g) / (0.1631 * 0.3 + 0.8766),
              1e-15);
}

TEST(LiggghtsScript, RefusesAStepAboveTwentyPercentOfTheRayleighTime) {
  DemSpec dem;
  const double t_r = rayleigh_time_s(dem);
  EXPECT_NO_THROW({
    DemSpec ok = dem;
    ok.time_step_s = 0.199 * t_r;
    validate(ok);
  });
  const std::string message = message_of_refused_step(0.21 * t_r, dem);
  ASSERT_FALSE(message.empty()) << "a step of 21 % of the Rayleigh time was accepted";
  EXPECT_NE(message.find("time_step_s"), std::string::npos) << message;
  EXPECT_NE(message.find(fmt::format("{:.6g}", 0.21 * t_r)), std::string::npos) << message;
  EXPECT_NE(message.find(fmt::format("{:.6g}", t_r)), std::string::npos) << message;
  EXPECT_NE(message.find(fmt::format("{:.6g}", 0.2 * t_r)), std::string::npos) << message;
  // and the scripts refuse it too
  Scene scene = testing::small_dem_scene(false);
  scene = with_dem_changed(std::move(scene), [&](DemSpec& d) { d.time_step_s = 0.5 * t_r; });
  EXPECT_THROW(bed_script(scene), InputError);
  EXPECT_THROW(run_script(scene), InputError);
}

TEST(LiggghtsScript, RefusesASceneWithoutDemAndBadParameters) {
  Scene scene = testing::small_dem_scene(false);
  scene.sections.erase(DemSection::kKey);
  EXPECT_THROW(bed_script(scene), InputError);
  DemSpec dem;
  dem.restitution = 0.0;
  EXPECT_THROW(validate(dem), InputError);
  dem = DemSpec{};
  dem.radius_spread = 0.5;
  EXPECT_THROW(validate(dem), InputError);
}

TEST(LiggghtsScript, RefusesBedsTooLargeToRun) {
  Scene scene = testing::small_dem_scene(false);
  scene.ground.grid.nx = scene.ground.grid.ny = 1000;  // 4 m x 4 m of 2 mm grains
  try {
    bed_script(scene);
    FAIL() << "a bed of millions of grains was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(std::to_string(bed_grain_count(scene, {}))), std::string::npos) << e.what();
  }
}

TEST(LiggghtsScript, SeedsArePrimesAboveTenThousandDistinctAndFromTheSceneSeed) {
  const auto seeds = liggghts_seeds(42, 7);
  ASSERT_EQ(seeds.size(), 7u);
  for (std::size_t k = 0; k < seeds.size(); ++k) {
    EXPECT_GT(seeds[k], 10000u);
    for (std::uint64_t d = 2; d * d <= seeds[k]; ++d) ASSERT_NE(seeds[k] % d, 0u) << seeds[k] << " is not prime";
    for (std::size_t j = 0; j < k; ++j) EXPECT_NE(seeds[k], seeds[j]);
  }
  EXPECT_EQ(seeds, liggghts_seeds(42, 7));
  EXPECT_NE(seeds, liggghts_seeds(43, 7));
}

TEST(LiggghtsScript, BedScriptIsDeterministicAndHoldsTheContactModel) {
  const Scene scene = testing::small_dem_scene(false);
  const std::string a = bed_script(scene);
  EXPECT_EQ(a, bed_script(scene));
  EXPECT_NE(a.find("pair_style gran model hertz tangential history rolling_friction cdt\n"), std::string::npos);
  for (const std::string& property :
       {"youngsModulus peratomtype " + liggghts_number(5e6), std::string("poissonsRatio peratomtype 0.3"),
        std::string("coefficientRestitution peratomtypepair 1 0.5"), std::string("coefficientFriction peratomtypepair 1 0.5"),
        std::string("coefficientRollingFriction peratomtypepair 1 0.1")}) {
    EXPECT_NE(a.find(property), std::string::npos) << property;
  }
  EXPECT_EQ(a.find("cohesion"), std::string::npos);
  EXPECT_NE(a.find("timestep " + liggghts_number(1e-5) + "\n"), std::string::npos);
  EXPECT_NE(a.find("fix gravity all gravity 9.81 vector 0 0 -1"), std::string::npos);
  EXPECT_NE(a.find(fmt::format("particles_in_region {}", bed_grain_count(scene, {}))), std::string::npos);
  EXPECT_NE(a.find("write_restart bed.restart"), std::string::npos);
  EXPECT_NE(a.find("dump_modify bed sort id"), std::string::npos);

  // the bed (and its cache key) does not depend on the scene's name or objects:
  // scenes on the same grid with the same grains and seed share one
  Scene pressed = testing::small_dem_scene(true);
  pressed.name = "another_scene";
  EXPECT_EQ(a, bed_script(pressed));

  Scene other = scene;
  other.seed = 8;
  EXPECT_NE(a, bed_script(other));
  other = scene;
  other = with_dem_changed(std::move(other), [&](DemSpec& d) { d.cohesion_energy_density_j_m3 = 3e5; });
  other = with_dem_changed(std::move(other), [&](DemSpec& d) { d.rolling_model = DemSpec::RollingModel::kEpsd2; });
  const std::string c = bed_script(other);
  // LIGGGHTS refuses cohesion after rolling_friction ("Unknown argument or wrong keyword order")
  EXPECT_NE(c.find("tangential history cohesion sjkr rolling_friction epsd2\n"), std::string::npos);
  EXPECT_NE(c.find("cohesionEnergyDensity peratomtypepair 1 " + liggghts_number(3e5)), std::string::npos);
}

TEST(LiggghtsScript, BedGrainCountFillsTheBedDepthAtThePackingFraction) {
  const Scene scene = testing::small_dem_scene(false);
  BedScriptOptions o;
  const double volume = bed_grain_count(scene, o) * mean_grain_volume_m3(*dem_of(scene));
  EXPECT_NEAR(volume / (0.04 * 0.04 * o.packing_fraction), dem_of(scene)->bed_depth_m, 1e-4);
  const auto radii = grain_radii_m(*dem_of(scene));
  ASSERT_EQ(radii.size(), 5u);
  EXPECT_DOUBLE_EQ(radii.front(), 0.0018);
  EXPECT_DOUBLE_EQ(radii.back(), 0.0022);
}

// The move/mesh segments must carry the object exactly between keyframes.
TEST(LiggghtsScript, RunScriptMovesObjectsThroughTheirKeyframes) {
  const Scene scene = testing::small_dem_scene(true);
  const RunScript r = run_script(scene);
  EXPECT_EQ(r.text, run_script(scene).text);
  ASSERT_EQ(r.meshes.size(), 1u);
  EXPECT_NE(r.text.find("fix obj0 all mesh/surface/stress file object_0.stl type 1 stress on"), std::string::npos);
  EXPECT_NE(r.text.find("wall/gran model hertz tangential history rolling_friction cdt mesh n_meshes 1 meshes obj0"),
            std::string::npos);
  EXPECT_NE(r.text.find("dump_modify grains sort id"), std::string::npos);
  EXPECT_EQ(r.total_steps, 20000);
  EXPECT_GT(r.domain.z_max_m, 0.023 + 0.008);
  // the mesh starts at the first keyframe
  EXPECT_NEAR(bounding_box(r.meshes[0].mesh).min.z(), 0.023 - 0.008, 1e-9);

  // integrate the segments: velocity x steps x dt = keyframe displacement
  std::istringstream lines(r.text);
  Eigen::Vector3d position(0.02, 0.02, 0.023), velocity = Eigen::Vector3d::Zero();
  std::vector<double> z_after_runs;
  const std::regex move(R"(fix move0_\d+ all move/mesh mesh obj0 linear (\S+) (\S+) (\S+))");
  const std::regex run(R"(run (\d+))");
  bool after_change_box = false;
  for (std::string line; std::getline(lines, line);) {
    std::smatch m;
    if (line.rfind("change_box", 0) == 0) after_change_box = true;
    if (std::regex_match(line, m, move)) velocity = {std::stod(m[1]), std::stod(m[2]), std::stod(m[3])};
    if (after_change_box && std::regex_match(line, m, run)) {
      position += velocity * std::stod(m[1]) * dem_of(scene)->time_step_s;
      z_after_runs.push_back(position.z());
    }
    if (line.rfind("unfix move", 0) == 0) velocity.setZero();
  }
  ASSERT_EQ(z_after_runs.size(), 2u);
  EXPECT_NEAR(z_after_runs[0], 0.014, 1e-12);
  EXPECT_NEAR(z_after_runs[1], 0.023, 1e-12);
}

// A rotating object: per segment a linear fix, then a rotate fix about the
// body origin whose angle over the segment is the slerp's; unfixed in reverse.
TEST(LiggghtsScript, RunScriptRotatesObjectsBetweenKeyframes) {
  Scene scene = testing::small_dem_scene(true);
  scene.objects[0].keyframes[1].pose.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()));
  const RunScript r = run_script(scene);
  EXPECT_EQ(r.text, run_script(scene).text);
  const std::regex rotate(
      R"(fix turn0_(\d) all move/mesh mesh obj0 rotate origin (\S+) (\S+) (\S+) axis (\S+) (\S+) (\S+) period (\S+))");
  std::vector<std::smatch> turns;
  for (auto it = std::sregex_iterator(r.text.begin(), r.text.end(), rotate); it != std::sregex_iterator(); ++it) {
    turns.push_back(*it);
  }
  ASSERT_EQ(turns.size(), 2u);
  const double span_s = 10000 * dem_of(scene)->time_step_s;  // each segment: 0.1 s
  for (std::size_t k = 0; k < 2; ++k) {
    const std::smatch& m = turns[k];
    // about x through the body origin at the segment's start (the top keyframe, then the bottom one)
    EXPECT_NEAR(std::stod(m[2]), 0.02, 1e-12);
    EXPECT_NEAR(std::stod(m[3]), 0.02, 1e-12);
    EXPECT_NEAR(std::stod(m[4]), k == 0 ? 0.023 : 0.014, 1e-12);
    const Eigen::Vector3d axis(std::stod(m[5]), std::stod(m[6]), std::stod(m[7]));
    EXPECT_NEAR(axis.dot(Eigen::Vector3d::UnitX()), k == 0 ? 1.0 : -1.0, 1e-12);  // there and back
    EXPECT_NEAR(2 * std::numbers::pi * span_s / std::stod(m[8]), 0.3, 1e-12);
  }
  // linear before rotate on the same mesh, unfixed in reverse order of creation
  const std::size_t linear = r.text.find("fix move0_0 all move/mesh mesh obj0 linear");
  const std::size_t turn = r.text.find("fix turn0_0 ");
  ASSERT_NE(linear, std::string::npos);
  ASSERT_NE(turn, std::string::npos);
  EXPECT_LT(linear, turn);
  EXPECT_NE(r.text.find("unfix turn0_0\nunfix move0_0\n"), std::string::npos);
  // the top of the box holds the body in any orientation
  EXPECT_GT(r.domain.z_max_m, 0.023 + 0.008);
  // an object that only turns gets no linear fix
  Scene spin = testing::small_dem_scene(true);
  for (Keyframe& k : spin.objects[0].keyframes) k.pose.position_m = Eigen::Vector3d(0.02, 0.02, 0.03);
  spin.objects[0].keyframes[2].pose.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(1.0, Eigen::Vector3d::UnitZ()));
  const RunScript only_turn = run_script(spin);
  EXPECT_EQ(only_turn.text.find(" linear "), std::string::npos);
  EXPECT_EQ(only_turn.text.find("fix turn0_0"), std::string::npos);  // first segment: no change
  EXPECT_NE(only_turn.text.find("fix turn0_1 all move/mesh mesh obj0 rotate origin 0.02 0.02 0.03 axis 0 0 1 period"),
            std::string::npos)
      << only_turn.text;
}

}  // namespace
}  // namespace repose
