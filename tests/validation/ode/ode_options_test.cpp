#include "validation/ode/ode_options.h"

#include <gtest/gtest.h>

#include <string>

#include "models/core/base/error.h"
#include "models/core/config/scene.h"
#include "models/core/config/scene_loader.h"
#include "tests/support/engine_section_checks.h"
#include "validation/particles/dem_section.h"
#include "validation/ode/ode_section.h"

namespace repose {
namespace {

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
      {"[1, 2]", "time_step_s"},  // not a map: the allowed keys are listed
  };
  test_support::expect_one_line_errors_naming_the_key(ode_section_type(), cases);
}

TEST(OdeOptions, InASceneTheErrorNamesTheFileLineAndKeyPath) {
  test_support::expect_scene_error_names_file_line_and_key(ode_section_type(), "ode: {time_step_s: 0.5}",
                                                           "ode.time_step_s");
  const Scene without = load_scene_from_string(test_support::dem_scene_with(""), "/tmp/scene.yaml",
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
