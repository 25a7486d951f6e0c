// `repose calibrate` end to end on the synthetic calibration (fast): the run
// folder holds calibration.json, a material.yaml that a scene accepts as its
// parameters.yaml, the report and figure data; a malformed file writes nothing.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <yaml-cpp/yaml.h>

#include "models/core/config/scene_loader.h"
#include "models/core/io/npy_io.h"
#include "experiments/solvers/solver_registry.h"
#include "tests/support/temp_dir.h"

namespace repose {
namespace {

namespace fs = std::filesystem;

const std::string kDir = std::string(REPOSE_SOURCE_DIR) + "/tests/data/calibration";

std::string read(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

int run(const std::string& arguments) {
  const std::string command = std::string(REPOSE_BINARY) + " " + arguments + " >/dev/null 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(CalibrationCommand, WritesTheRunFolder) {
  const test_support::TempDir temp;
  const fs::path out = temp.path / "out";
  ASSERT_EQ(run("calibrate " + kDir + "/synthetic.yaml --out " + out.string()), 0);
  for (const char* name : {"calibration.json", "parameters.yaml", "report.md", "manifest.json",
                           "data/calib_indent_reference.npy", "data/calib_indent_heuristic_fitted.npy"}) {
    EXPECT_TRUE(fs::exists(out / name)) << name;
  }
  const std::string json = read(out / "calibration.json");
  for (const char* key : {"\"standard_error\"", "\"correlation\"", "\"initial_cost\"", "\"final_cost\"",
                          "\"rmse_initial_m\"", "\"rmse_fitted_m\"", "\"iterations\"", "\"termination\"", "\"wall_time_s\""}) {
    EXPECT_NE(json.find(key), std::string::npos) << key;
  }
  // parameters.yaml: the fitted values by full name, in their units (the
  // synthetic reference's are alpha 0.7, 35 deg, sigma 0.15)
  const YAML::Node fitted = YAML::LoadFile((out / "parameters.yaml").string());
  EXPECT_NEAR(fitted["ground.sand.alpha"].as<double>(), 0.7, 0.02);
  EXPECT_NEAR(fitted["ground.sand.repose_angle_deg"].as<double>(), 35.0, 1.0);
  EXPECT_NEAR(fitted["ground.sand.sigma"].as<double>(), 0.15, 0.02);
  // ... to the last bit of the fit's double, so a rerun at them is the fit's run
  const nlohmann::json calibration = nlohmann::json::parse(json);
  for (const nlohmann::json& p : calibration["parameters"]) {
    if (p["name"] == "ground.sand.repose_angle_deg") continue;  // converted from radians
    EXPECT_EQ(fitted[p["name"].get<std::string>()].as<double>(), p["value"].get<double>()) << p["name"];
  }
}

// Cross-validation's folds in the run folder: per fold its values and what
// it predicts for the scenes it did not fit, series included
// (tests/data/calibration/scoop_cv.yaml: two scoops fitted, one held out).
TEST(CalibrationCommand, WritesWhatEachFoldPredictsWithItsSeries) {
  const test_support::TempDir temp;
  const fs::path out = temp.path / "out";
  ASSERT_EQ(run("calibrate " + kDir + "/scoop_cv.yaml --out " + out.string()), 0);
  const nlohmann::json folds = nlohmann::json::parse(read(out / "calibration.json"))["cross_validation"];
  ASSERT_EQ(folds.size(), 2u);
  for (const nlohmann::json& fold : folds) {
    EXPECT_TRUE(fold["values"].contains("heightspan.sand.repose_angle_deg"));
    EXPECT_GT(fold["iterations"].get<int>(), 0);
    EXPECT_FALSE(fold["termination"].get<std::string>().empty());
    ASSERT_EQ(fold["predicted"].size(), 2u) << "the left-out scoop and the held-out one";
    EXPECT_EQ(fold["predicted"][0]["name"], fold["left_out"]);
    EXPECT_EQ(fold["predicted"][0]["role"], "left_out");
    EXPECT_EQ(fold["predicted"][1]["name"], "scoop_held");
    EXPECT_EQ(fold["predicted"][1]["role"], "held_out");
    for (const nlohmann::json& p : fold["predicted"]) {
      ASSERT_EQ(p["series"].size(), 1u);
      EXPECT_EQ(p["series"][0]["name"], "mass_held_kg.bucket");
      EXPECT_EQ(p["series"][0]["fitted_relative_error"].size(), 3u);
      EXPECT_TRUE(p["scores"].contains("rmse_m"));
    }
  }
  const std::string report = read(out / "report.md");
  EXPECT_NE(report.find("## Cross-validation: what each fold predicts"), std::string::npos);
  const std::string iterations = std::to_string(folds[1]["iterations"].get<int>());
  EXPECT_NE(report.find("| scoop_b | " + iterations + " | scoop_held | held out |"), std::string::npos) << report;
}

TEST(CalibrationCommand, MalformedFileWritesNothingAndExitsTwo) {
  const test_support::TempDir temp;
  const fs::path out = temp.path / "out";
  EXPECT_EQ(run("calibrate " + kDir + "/bad/bad_loss.yaml --out " + out.string()), 2);
  EXPECT_FALSE(fs::exists(out));
}

// A reference of the wrong shape is found before the output folder is made,
// and the one-line message names the calibration file's line.
TEST(CalibrationCommand, AReferenceOfTheWrongShapeNamesItsLineAndWritesNothing) {
  const test_support::TempDir temp;
  const fs::path& work = temp.path;
  fs::create_directories(work / "ref");
  write_npy_2d((work / "ref" / "height_initial.npy").string(), ArrayXXdR::Zero(3, 4));
  write_npy_2d((work / "ref" / "height_final.npy").string(), ArrayXXdR::Zero(3, 4));
  std::ofstream(work / "calib.yaml") << "scenes:\n  - scene: " << kDir << "/scenes/indent.yaml\n"
                                     << "    reference: {data: ref}\n    observables: [{kind: height_field}]\n"
                                     << "parameters: [{name: ground.sand.alpha, initial: 0.5}]\n";
  const fs::path out = work / "out";
  const std::string err = (work / "err.txt").string();
  const std::string command = std::string(REPOSE_BINARY) + " calibrate " + (work / "calib.yaml").string() +
                              " --out " + out.string() + " >/dev/null 2>" + err;
  const int status = std::system(command.c_str());
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 2);
  const std::string message = read(err);
  EXPECT_NE(message.find((work / "calib.yaml").string() + ":3:16: reference: "), std::string::npos) << message;
  EXPECT_NE(message.find("3 rows x 4 columns"), std::string::npos) << message;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(fs::exists(work / ".out.tmp"));
}

}  // namespace
}  // namespace repose
