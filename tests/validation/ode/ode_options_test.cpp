#include "validation/ode/ode_options.h"

#include <gtest/gtest.h>

#include <string>

#include "models/core/base/error.h"
#include "models/core/config/scene.h"
#include "models/core/config/scene_loader.h"
#include "validation/particles/dem_section.h"
#include "validation/ode/ode_section.h"

namespace repose {
namespace {

// The one-line error of reading `section` as a bullet: section.
std::string error_of(const std::string& section) {
  try {
    ode_section_type().read(parse_yaml(section, "scene.yaml"), Scene{});
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(OdeOptions, AbsentKeysKeepTheDocumentedDefaults) {
  const auto section = ode_section_type().read(parse_yaml("{solver_iterations: 15}", "scene.yaml"), Scene{});
  const OdeOptions& o = dynamic_cast<const OdeSection&>(*section).options;
  EXPECT_EQ(o.rigid.solver_iterations, 15);
  EXPECT_EQ(OdeOptions{}.rigid.solver_iterations, 20);
  EXPECT_DOUBLE_EQ(o.rigid.time_step_s, 1.0 / 600.0);
  EXPECT_DOUBLE_EQ(o.erp, 0.2);
}

TEST(OdeOptions, MalformedSectionsGiveOneLineErrorsNamingTheKey) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"{time_step_s: -0.001}", "time_step_s"},
      {"{solver_iterations: 0}", "solver_iterations"},
      {"{erp: 1.5}", "erp"},
      {"{cfm: 0}", "cfm"},
      {"{substeps: 3}", "substeps"},  // unknown key
      {"{time_step_s: 0.01, settle_check_interval_s: 0.001}", "settle_check_interval_s"},
      {"[1, 2]", "time_step_s"},      // not a map: the allowed keys are listed
  };
  for (const auto& [section, key] : cases) {
    const std::string message = error_of(section);
    EXPECT_NE(message.find(key), std::string::npos) << section << " -> " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

TEST(OdeOptions, InASceneTheErrorNamesTheFileLineAndKeyPath) {
  const std::string scene =
      "time: {step_s: 0.01, duration_s: 0.1}\n"
      "ground: {extent_m: [0.04, 0.04], cell_size_m: 0.004, initial_height: {kind: flat, height_m: 0.01}}\n"
      "dem: {bed_depth_m: 0.01}\n"
      "ode: {time_step_s: 0.5}\n";
  try {
    load_scene_from_string(scene, "/tmp/scene.yaml", {dem_section_type(), ode_section_type()});
    FAIL() << "accepted a step of 0.5 s";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/tmp/scene.yaml:4:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("ode.time_step_s"), std::string::npos) << e.what();
  }
  const Scene without = load_scene_from_string(scene.substr(0, scene.rfind("ode:")), "/tmp/scene.yaml",
                                               {dem_section_type(), ode_section_type()});
  EXPECT_EQ(ode_options_text(ode_options_of(without)), ode_options_text(OdeOptions{}));
}

TEST(OdeOptions, ValidateNamesTheField) {
  OdeOptions o;
  o.surface_layer_fraction = -1.0;
  try {
    validate(o);
    FAIL() << "accepted a negative slop";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("surface_layer_fraction"), std::string::npos) << e.what();
  }
}

TEST(OdeOptions, TheTextOfTheOptionsChangesWithEveryField) {
  OdeOptions a, b;
  b.max_contacts_per_pair = 5;
  EXPECT_NE(ode_options_text(a), ode_options_text(b));
  EXPECT_EQ(ode_options_text(a), ode_options_text(OdeOptions{}));
}

}  // namespace
}  // namespace repose
