#include "models/heightspan/heightspan_solver.h"

#include <algorithm>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "experiments/solvers/solver_registry.h"
#include "heightspan_fixtures.h"
#include "models/core/base/error.h"
#include "models/core/config/scene_loader.h"
#include "models/ground/ground_solver.h"
#include "tests/support/temp_dir.h"

namespace repose {
namespace {

using testing::key;

Scene small_scoop() {
  std::vector<Keyframe> keys = {key(0.0, 0.06, 0.06, 0.1, 80), key(0.2, 0.06, 0.06, 0.055, 80),
                                key(0.5, 0.1, 0.06, 0.055, 80), key(0.7, 0.1, 0.06, 0.12, 0)};
  return testing::bed_scene(40, 24, 0.005, 0.03, {testing::mesh_object("bucket", testing::bucket_mesh(), keys)}, 24);
}

TEST(HeightSpanSolver, IsRegisteredAndDeclaresTheGroundsParametersByTheirNames) {
  const Solver& solver = solver_registry().get("heightspan");
  const Scene s = small_scoop();
  const auto compiled = solver.compile(s);
  const auto ground = GroundSolver().compile(s);
  // the ground's, then its own intake layer and fraction, wedge fractions, press fraction, pressed wedge, side cut,
  // over-lip share, release speed and shear layer
  ASSERT_EQ(compiled->parameters().size(), ground->parameters().size() + 10);
  const std::vector<std::pair<std::string, double>> own = {
      {"intake_layer_m", HeightSpanSpec{}.intake_layer_m}, {"intake_fraction", HeightSpanSpec{}.intake_fraction},
      {"wedge_fraction", HeightSpanSpec{}.wedge_fraction},
      {"lip_wedge_fraction", HeightSpanSpec{}.lip_wedge_fraction}, {"press_fraction", HeightSpanSpec{}.press_fraction},
      {"press_wedge_fraction", HeightSpanSpec{}.press_wedge_fraction},
      {"side_cut_m", HeightSpanSpec{}.side_cut_m}, {"over_lip_fraction", HeightSpanSpec{}.over_lip_fraction},
      {"release_speed_m_s", HeightSpanSpec{}.release_speed_m_s}, {"shear_layer_m", HeightSpanSpec{}.shear_layer_m}};
  for (std::size_t k = 0; k < own.size(); ++k) {
    const ParameterInfo& p = compiled->parameters()[ground->parameters().size() + k];
    EXPECT_EQ(p.name, own[k].first);
    EXPECT_EQ(p.value_si, own[k].second) << p.name;
  }
  for (std::size_t k = 0; k < ground->parameters().size(); ++k) {
    EXPECT_EQ(compiled->parameters()[k].name, ground->parameters()[k].name);
    EXPECT_EQ(compiled->parameters()[k].value_si, ground->parameters()[k].value_si);
  }
  EXPECT_NO_THROW(compiled->parameter_index("sand.repose_angle_deg"));
  std::vector<double> values = compiled->default_values();
  values[compiled->parameter_index("sand.sigma")] = 0.3;  // above the stability limit
  EXPECT_THROW(compiled->run(values, {}), InputError);
}

TEST(HeightSpanSolver, AFittedIntakeLayerReachesTheRun) {
  // a thin intake layer holds less than no limit on the same scoop
  const auto compiled = HeightSpanSolver().compile(small_scoop());
  std::vector<double> values = compiled->default_values();
  const double all = compiled->run(values, {}).measure("mass_held_max_kg.bucket").value;
  values[compiled->parameter_index("intake_layer_m")] = 0.0005;
  const double thin = compiled->run(values, {}).measure("mass_held_max_kg.bucket").value;
  EXPECT_GT(thin, 0.0);
  EXPECT_LT(thin, all);
  values[compiled->parameter_index("intake_layer_m")] = 0.0;
  EXPECT_THROW(compiled->run(values, {}), InputError);
}

TEST(HeightSpanSolver, AFittedIntakeFractionReachesTheRun) {
  // a lip that takes in a share of what it meets holds less than one that takes in all
  const auto compiled = HeightSpanSolver().compile(small_scoop());
  std::vector<double> values = compiled->default_values();
  const double all = compiled->run(values, {}).measure("mass_held_max_kg.bucket").value;
  values[compiled->parameter_index("intake_fraction")] = 0.3;
  const repose::Run part = compiled->run(values, {});
  EXPECT_GT(part.measure("mass_held_max_kg.bucket").value, 0.0);
  EXPECT_LT(part.measure("mass_held_max_kg.bucket").value, all);
  EXPECT_LT(part.measure("ledger.max_relative_imbalance").value, 1e-12);
  values[compiled->parameter_index("intake_fraction")] = 0.0;
  EXPECT_THROW(compiled->run(values, {}), InputError);
}

TEST(HeightSpanSolver, AFittedReleaseSpeedReachesTheRun) {
  // what spills off the lifted bucket lands elsewhere when it leaves faster; below 0 refused
  const auto compiled = HeightSpanSolver().compile(small_scoop());
  std::vector<double> values = compiled->default_values();
  const repose::Run still = compiled->run(values, {});
  ASSERT_GT(still.measure("flows.span_to_particles_m3").value, 0.0);
  values[compiled->parameter_index("release_speed_m_s")] = 0.5;
  const repose::Run thrown = compiled->run(values, {});
  EXPECT_FALSE((thrown.field("height_final").heights() == still.field("height_final").heights()).all());
  EXPECT_LT(thrown.measure("ledger.max_relative_imbalance").value, 1e-12);
  values[compiled->parameter_index("release_speed_m_s")] = -0.1;
  EXPECT_THROW(compiled->run(values, {}), InputError);
}

TEST(HeightSpanSolver, AFittedPressedWedgeReachesTheRun) {
  // what lowering the bucket compresses is driven ahead by its drag and laid where the drag ends, so the run
  // compresses less by exactly that and the ground keeps it; beyond [0, 1] refused
  const auto compiled = HeightSpanSolver().compile(small_scoop());
  std::vector<double> values = compiled->default_values();
  values[compiled->parameter_index("sand.alpha")] = 0.3;
  const repose::Run pressed = compiled->run(values, {});
  ASSERT_GT(pressed.measure("volume.compressed_m3").value, 0.0);
  values[compiled->parameter_index("press_wedge_fraction")] = 1.0;
  const repose::Run driven = compiled->run(values, {});
  EXPECT_LT(driven.measure("volume.compressed_m3").value, pressed.measure("volume.compressed_m3").value);
  EXPECT_GT(driven.measure("flows.wedge_laid_m3").value, pressed.measure("flows.wedge_laid_m3").value);
  EXPECT_GT(driven.measure("volume.ground_final_m3").value, pressed.measure("volume.ground_final_m3").value);
  EXPECT_EQ(driven.measure("volume.wedge_final_m3").value, 0.0);
  EXPECT_LT(driven.measure("ledger.max_relative_imbalance").value, 1e-12);
  values[compiled->parameter_index("press_wedge_fraction")] = 1.5;
  EXPECT_THROW(compiled->run(values, {}), InputError);
}

TEST(HeightSpanSolver, AFittedWedgeFractionReachesTheRun) {
  // a drag that keeps its wedge lays it when the drag ends; none without; beyond [0, 1] refused
  const auto compiled = HeightSpanSolver().compile(small_scoop());
  std::vector<double> values = compiled->default_values();
  values[compiled->parameter_index("sand.alpha")] = 0.3;  // the drag compresses 70 % of what it displaces
  EXPECT_EQ(compiled->run(values, {}).measure("flows.wedge_kept_m3").value, 0.0);
  values[compiled->parameter_index("wedge_fraction")] = 1.0;
  const repose::Run kept = compiled->run(values, {});
  EXPECT_GT(kept.measure("flows.wedge_kept_m3").value, 0.0);
  EXPECT_LT(kept.measure("ledger.max_relative_imbalance").value, 1e-12);
  values[compiled->parameter_index("wedge_fraction")] = 1.5;
  EXPECT_THROW(compiled->run(values, {}), InputError);
}

TEST(HeightSpanSolver, AFittedLipWedgeFractionReachesTheRunOnlyWithTheSplitSource) {
  // a thin intake layer makes the lip push ahead; with wedge_source split its fraction of that is kept
  Scene s = small_scoop();
  HeightSpanSection section = heightspan_section(s);
  section.options.intake_layer_m = 0.002;
  const auto other = HeightSpanSolver().compile(with_heightspan(s, section));
  section.options.wedge_source = HeightSpanSpec::WedgeSource::kSplit;
  const auto split = HeightSpanSolver().compile(with_heightspan(s, section));
  std::vector<double> values = split->default_values();
  EXPECT_EQ(split->run(values, {}).measure("flows.wedge_kept_m3").value, 0.0);
  values[split->parameter_index("lip_wedge_fraction")] = 1.0;
  const repose::Run kept = split->run(values, {});
  EXPECT_GT(kept.measure("flows.wedge_kept_m3").value, 0.0);
  EXPECT_LT(kept.measure("ledger.max_relative_imbalance").value, 1e-12);
  EXPECT_THROW(other->run(values, {}), InputError);  // the compression's source would ignore it: refused
}

TEST(HeightSpanSolver, AFittedPressFractionReachesTheRun) {
  // the lowering compresses less when the bucket displaces what it presses; beyond [0, 1] refused
  const auto compiled = HeightSpanSolver().compile(small_scoop());
  std::vector<double> values = compiled->default_values();
  values[compiled->parameter_index("sand.alpha")] = 0.3;
  const double compressed = compiled->run(values, {}).measure("volume.compressed_m3").value;
  values[compiled->parameter_index("press_fraction")] = 1.0;
  const repose::Run displaced = compiled->run(values, {});
  EXPECT_GT(compressed, 0.0);
  EXPECT_LT(displaced.measure("volume.compressed_m3").value, compressed);
  EXPECT_LT(displaced.measure("ledger.max_relative_imbalance").value, 1e-12);
  values[compiled->parameter_index("press_fraction")] = -0.5;
  EXPECT_THROW(compiled->run(values, {}), InputError);
}

TEST(HeightSpanSolver, AFittedSideCutReachesTheRun) {
  // a drag that cuts beside its walls reports the cut (into the wedge, laid when the drag ends)
  const auto compiled = HeightSpanSolver().compile(small_scoop());
  std::vector<double> values = compiled->default_values();
  EXPECT_EQ(compiled->run(values, {}).measure("flows.side_cut_m3").value, 0.0);
  values[compiled->parameter_index("side_cut_m")] = 0.005;
  const repose::Run cut = compiled->run(values, {});
  EXPECT_GT(cut.measure("flows.side_cut_m3").value, 0.0);
  EXPECT_GE(cut.measure("flows.wedge_kept_m3").value, cut.measure("flows.side_cut_m3").value);
  EXPECT_LT(cut.measure("ledger.max_relative_imbalance").value, 1e-12);
  values[compiled->parameter_index("side_cut_m")] = -0.001;
  EXPECT_THROW(compiled->run(values, {}), InputError);
}

TEST(HeightSpanSolver, AFittedShearLayerDeepensTheTrenchAndKeepsTheLedger) {
  // the bucket's underside meets the ground 3 mm lower: the drag leaves a deeper trench, and nothing is lost
  const auto compiled = HeightSpanSolver().compile(small_scoop());
  std::vector<double> values = compiled->default_values();
  const auto deepest_m = [](const repose::Run& r) {
    return (r.field("height_initial").heights() - r.field("height_final").heights()).maxCoeff();
  };
  const repose::Run plain = compiled->run(values, {});
  values[compiled->parameter_index("shear_layer_m")] = 0.003;
  const repose::Run sheared = compiled->run(values, {});
  EXPECT_GT(deepest_m(sheared), deepest_m(plain) + 0.001);
  EXPECT_LT(sheared.measure("ledger.max_relative_imbalance").value, 1e-12);
  values[compiled->parameter_index("shear_layer_m")] = 0.06;
  EXPECT_THROW(compiled->run(values, {}), InputError);
}

TEST(HeightSpanSolver, AFittedOverLipShareReachesTheRun) {
  // a drag with a wedge sends that share of it into the bucket and reports it
  const auto compiled = HeightSpanSolver().compile(small_scoop());
  std::vector<double> values = compiled->default_values();
  values[compiled->parameter_index("sand.alpha")] = 0.3;
  values[compiled->parameter_index("wedge_fraction")] = 1.0;
  EXPECT_EQ(compiled->run(values, {}).measure("flows.over_lip_m3").value, 0.0);
  values[compiled->parameter_index("over_lip_fraction")] = 0.4;
  const repose::Run fed = compiled->run(values, {});
  EXPECT_GT(fed.measure("flows.over_lip_m3").value, 0.0);
  EXPECT_NEAR(fed.measure("flows.over_lip_m3").value, 0.4 * fed.measure("flows.wedge_kept_m3").value,
              1e-9 * fed.measure("flows.wedge_kept_m3").value);
  EXPECT_LT(fed.measure("ledger.max_relative_imbalance").value, 1e-12);
  values[compiled->parameter_index("wedge_fraction")] = 0.0;  // a share of no wedge
  EXPECT_THROW(compiled->run(values, {}), InputError);
}

TEST(HeightSpanSolver, RunsReportTheLedgerTheHeldMassAndWhatWasBuilt) {
  const auto compiled = HeightSpanSolver().compile(small_scoop());
  const repose::Run run = compiled->run(compiled->default_values(), {});
  EXPECT_EQ(run.solver, "heightspan");
  EXPECT_LT(run.measure("ledger.max_relative_imbalance").value, 1e-12);
  EXPECT_GT(run.measure("mass_held_max_kg.bucket").value, 0.0);
  EXPECT_EQ(run.measure("mass_held_kg.bucket").unit, "kg");
  EXPECT_EQ(run.details["built"]["span_maps"], nlohmann::json::array({"bucket"}));
  EXPECT_TRUE(run.files.empty());  // no output folder: no files
  EXPECT_NO_THROW(run.field("height_final"));
  // the held mass at every step: its last value and its largest are the measures
  const TimeSeries& held = run.series.at("mass_held_kg.bucket");
  EXPECT_EQ(held.unit, "kg");
  ASSERT_EQ(held.time_s.size(), static_cast<std::size_t>(run.measure("steps").value));
  EXPECT_EQ(held.value.back(), run.measure("mass_held_kg.bucket").value);
  EXPECT_EQ(*std::max_element(held.value.begin(), held.value.end()), run.measure("mass_held_max_kg.bucket").value);
}

TEST(HeightSpanSolver, ASceneWithNothingToHoldRunsTheGroundModel) {
  Scene s = testing::bed_scene(40, 40, 0.005, 0.02,
                               {testing::mesh_object("ball", make_sphere(0.02), {key(0, 0.1, 0.1, 0.035), key(1, 0.1, 0.1, 0.02)})},
                               10);
  HeightSpanSection section = heightspan_section(s);
  section.holds_material.clear();
  s = with_heightspan(s, section);
  const auto compiled = HeightSpanSolver().compile(s);
  const repose::Run hs = compiled->run(compiled->default_values(), {});
  const auto ground = GroundSolver().compile(s);
  const repose::Run g = ground->run(ground->default_values(), {});
  EXPECT_TRUE((hs.field("height_final").heights() == g.field("height_final").heights()).all());
  EXPECT_EQ(hs.details["built"]["span_maps"], nlohmann::json::array());
  EXPECT_EQ(hs.details["built"]["particles"], false);
  EXPECT_EQ(hs.details["built"]["ground_path_objects"], nlohmann::json::array({"ball"}));
}

TEST(HeightSpanSolver, WithAnOutputFolderItWritesTheHeldMassAndFrames) {
  Scene s = small_scoop();
  HeightSpanSection section = heightspan_section(s);
  section.options.frame_interval_s = 0.4;
  s = with_heightspan(s, section);
  const test_support::TempDir temp;
  const std::filesystem::path& dir = temp.path;
  const auto compiled = HeightSpanSolver().compile(s);
  const repose::Run run = compiled->run(compiled->default_values(), {{}, dir.string()});
  EXPECT_NE(std::find(run.files.begin(), run.files.end(), "held_mass.csv"), run.files.end());
  EXPECT_NE(std::find(run.files.begin(), run.files.end(), "frames/frame_0001.png"), run.files.end());
  for (const std::string& f : run.files) EXPECT_TRUE(std::filesystem::exists(dir / f)) << f;
  std::ifstream csv(dir / "held_mass.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header, "time_s,bucket_volume_m3,bucket_mass_kg,in_flight_m3,ledger_imbalance_m3");
  int rows = 0;
  for (std::string line; std::getline(csv, line);) ++rows;
  EXPECT_EQ(rows, 24);
}

TEST(HeightSpanSolver, TheScoopSceneLoadsForTheHeightSpanModelAndLiggghts) {
  const Scene s = load_scene(std::string(REPOSE_SOURCE_DIR) + "/experiments/scenes/heightspan_scoop.yaml",
                             solver_registry().sections());
  std::string why;
  EXPECT_TRUE(solver_registry().get("heightspan").can_run(s, &why)) << why;
  EXPECT_TRUE(solver_registry().get("liggghts").can_run(s, &why)) << why;
  EXPECT_NO_THROW(solver_registry().get("liggghts").compile(s));
}

}  // namespace
}  // namespace repose
