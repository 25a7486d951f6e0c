// The paper-fit file: the shipped one loads with its published values and
// parameters in the solver's order; a bad entry is refused at its key.
#include "experiments/tearing/paper_fit_spec.h"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "tests/support/temp_dir.h"

namespace repose {
namespace {

TEST(PaperFitSpec, TheShippedFileLoads) {
  const PaperFitSpec s = load_paper_fit_spec(std::string(REPOSE_SOURCE_DIR) + "/experiments/tearing_paper_fit.yaml");
  EXPECT_FALSE(s.source.empty());
  EXPECT_TRUE(std::filesystem::exists(s.tensile_scene)) << s.tensile_scene;
  EXPECT_TRUE(std::filesystem::exists(s.tear_scene)) << s.tear_scene;
  ASSERT_EQ(s.parameters.size(), 3u);
  EXPECT_EQ(s.parameters[0].name, "stiffness_scale");
  EXPECT_EQ(s.parameters[2].name, "fibre_anisotropy");
  EXPECT_GT(s.md_strength_n_per_m, s.cd_strength_n_per_m);
  for (const PaperFitParameter& p : s.parameters) {
    EXPECT_LE(p.lower, p.initial);
    EXPECT_LE(p.initial, p.upper);
  }
}

// The sack kraft file holds the HS Chapter 48 note's 80 g/m^2 row: its
// strengths in N/m (the table's kN/m x 1e3) and its tear resistances in mN,
// whose ratio is the check's published ratio.
TEST(PaperFitSpec, TheSackKraftFileLoadsItsPublishedValuesInTheirUnits) {
  const PaperFitSpec s =
      load_paper_fit_spec(std::string(REPOSE_SOURCE_DIR) + "/experiments/tearing_paper_fit_sack_kraft.yaml");
  EXPECT_DOUBLE_EQ(s.md_strength_n_per_m, (8.3 - 2.8) * 1e3);
  EXPECT_DOUBLE_EQ(s.cd_strength_n_per_m, 2.8e3);
  EXPECT_DOUBLE_EQ(s.md_tear_mn, 965.0);
  EXPECT_DOUBLE_EQ(s.cd_tear_mn, 2070.0 - 965.0);
  EXPECT_DOUBLE_EQ(s.tear_cd_over_md, 1105.0 / 965.0);
  EXPECT_NE(s.source.find("HS Chapter 48"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(s.tear_scene)) << s.tear_scene;
}

std::string error_of_published(const std::string& tear) {
  const test_support::TempDir dir;
  const std::filesystem::path path = dir.path / "fit.yaml";
  std::ofstream(path) << "name: t\nsource: s\ntensile_scene: a.yaml\nseeds: [1]\n"
                         "published: {md_stiffness_n_per_m: 1, cd_stiffness_n_per_m: 1, md_strength_n_per_m: 1,"
                         " cd_strength_n_per_m: 1, " << tear << "}\nparameters:\n"
                         "  - {name: stiffness_scale, initial: 1, bounds: [0, 2], step: 0.1}\n"
                         "  - {name: tear_strain, initial: 0.02, bounds: [0.01, 0.1], step: 0.001}\n"
                         "  - {name: fibre_anisotropy, initial: 0.2, bounds: [0, 0.9], step: 0.03}\n";
  try {
    load_paper_fit_spec(path.string());
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(PaperFitSpec, TakesTheTearRatioOrBothTearResistancesButNotBoth) {
  EXPECT_EQ(error_of_published("tear_cd_over_md: 1.1"), "accepted");
  EXPECT_EQ(error_of_published("md_tear_mn: 965, cd_tear_mn: 1105"), "accepted");
  EXPECT_NE(error_of_published("tear_cd_over_md: 1.1, md_tear_mn: 965").find("tear_cd_over_md"), std::string::npos);
  EXPECT_NE(error_of_published("md_tear_mn: 965").find("cd_tear_mn"), std::string::npos);
  EXPECT_NE(error_of_published("md_tear_mn: -965, cd_tear_mn: 1105").find("md_tear_mn"), std::string::npos);
}

std::string error_of(const std::string& parameters) {
  const test_support::TempDir dir;
  const std::filesystem::path path = dir.path / "fit.yaml";
  std::ofstream(path) << "name: t\nsource: s\ntensile_scene: a.yaml\nseeds: [1]\n"
                         "published: {md_stiffness_n_per_m: 1, cd_stiffness_n_per_m: 1, md_strength_n_per_m: 1,"
                         " cd_strength_n_per_m: 1, tear_cd_over_md: 1}\nparameters:\n" << parameters;
  try {
    load_paper_fit_spec(path.string());
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(PaperFitSpec, RefusesBoundsWithoutTheInitialValueAndParametersOutOfOrder) {
  const std::string good = "  - {name: stiffness_scale, initial: 1, bounds: [0, 2], step: 0.1}\n"
                           "  - {name: tear_strain, initial: 0.02, bounds: [0.01, 0.1], step: 0.001}\n";
  EXPECT_EQ(error_of(good + "  - {name: fibre_anisotropy, initial: 0.2, bounds: [0, 0.9], step: 0.03}\n"), "accepted");
  EXPECT_NE(error_of(good + "  - {name: fibre_anisotropy, initial: 0.95, bounds: [0, 0.9], step: 0.03}\n").find("bounds"),
            std::string::npos);
  EXPECT_NE(error_of(good + "  - {name: anisotropy, initial: 0.2, bounds: [0, 0.9], step: 0.03}\n").find("name"),
            std::string::npos);
  EXPECT_NE(error_of(good + "  - {name: fibre_anisotropy, initial: 0.2, bounds: [0, 0.9], step: 0}\n").find("step"),
            std::string::npos);
}

TEST(PaperFitSpec, AFourthParameterIsTheBackgroundDensityFittedToTheTearRatioOfATearScene) {
  const std::string good = "  - {name: stiffness_scale, initial: 1, bounds: [0, 2], step: 0.1}\n"
                           "  - {name: tear_strain, initial: 0.02, bounds: [0.01, 0.1], step: 0.001}\n"
                           "  - {name: fibre_anisotropy, initial: 0.2, bounds: [0, 0.9], step: 0.03}\n";
  // error_of's file has no tear scene: the ratio it would be fitted to is missing
  EXPECT_NE(error_of(good + "  - {name: background_density, initial: 0.4, bounds: [0.05, 0.8], step: 0.03}\n")
                .find("tear_scene"),
            std::string::npos);
  EXPECT_NE(error_of(good + "  - {name: clump_width, initial: 0.4, bounds: [0.05, 0.8], step: 0.03}\n").find("name"),
            std::string::npos);
  const PaperFitSpec s =
      load_paper_fit_spec(std::string(REPOSE_SOURCE_DIR) + "/experiments/tearing_paper_fit_sack_kraft_tear.yaml");
  ASSERT_EQ(s.parameters.size(), 4u);
  EXPECT_EQ(s.parameters[3].name, "background_density");
  EXPECT_GE(s.parameters[3].lower, 0.0);
  EXPECT_LT(s.parameters[3].upper, 1.0);
  EXPECT_FALSE(s.fit_tear_seeds.empty());
  EXPECT_DOUBLE_EQ(s.tear_cd_over_md, 1105.0 / 965.0);
}

}  // namespace
}  // namespace repose
