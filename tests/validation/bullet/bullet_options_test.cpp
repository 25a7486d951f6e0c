#include "validation/bullet/bullet_options.h"

#include <gtest/gtest.h>

#include <string>

#include "models/core/base/error.h"
#include "models/core/config/scene.h"
#include "models/core/config/scene_loader.h"
#include "tests/support/engine_section_checks.h"
#include "validation/particles/dem_section.h"
#include "validation/bullet/bullet_section.h"

namespace repose {
namespace {

TEST(BulletOptions, AbsentKeysKeepTheDocumentedDefaults) {
  const auto section = bullet_section_type().read(parse_yaml("{solver_iterations: 15}", "scene.yaml"), Scene{});
  const BulletOptions& o = dynamic_cast<const BulletSection&>(*section).options;
  EXPECT_EQ(o.rigid.solver_iterations, 15);
  EXPECT_DOUBLE_EQ(o.rigid.time_step_s, 1.0 / 600.0);
  EXPECT_DOUBLE_EQ(o.erp, 0.2);
}

TEST(BulletOptions, MalformedSectionsGiveOneLineErrorsNamingTheKey) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"{time_step_s: -0.001}", "time_step_s"},
      {"{solver_iterations: 0}", "solver_iterations"},
      {"{erp: 1.5}", "erp"},
      {"{contact_breaking_fraction: abc}", "contact_breaking_fraction"},
      {"{substeps: 3}", "substeps"},  // unknown key
      {"{time_step_s: 0.01, settle_check_interval_s: 0.001}", "settle_check_interval_s"},
      {"[1, 2]", "time_step_s"},  // not a map: the allowed keys are listed
  };
  test_support::expect_one_line_errors_naming_the_key(bullet_section_type(), cases);
}

TEST(BulletOptions, InASceneTheErrorNamesTheFileLineAndKeyPath) {
  test_support::expect_scene_error_names_file_line_and_key(bullet_section_type(), "bullet: {time_step_s: 0.5}",
                                                           "bullet.time_step_s");
  const Scene without = load_scene_from_string(test_support::dem_scene_with(""), "/tmp/scene.yaml",
                                               {dem_section_type(), bullet_section_type()});
  EXPECT_EQ(bullet_options_text(bullet_options_of(without)), bullet_options_text(BulletOptions{}));
}

TEST(BulletOptions, ValidateNamesTheField) {
  BulletOptions o;
  o.linear_slop_fraction = -1.0;
  try {
    validate(o);
    FAIL() << "accepted a negative slop";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("linear_slop_fraction"), std::string::npos) << e.what();
  }
}

TEST(BulletOptions, TheTextOfTheOptionsChangesWithEveryField) {
  BulletOptions a, b;
  b.shape_margin_fraction = 0.06;
  EXPECT_NE(bullet_options_text(a), bullet_options_text(b));
  EXPECT_EQ(bullet_options_text(a), bullet_options_text(BulletOptions{}));
}

}  // namespace
}  // namespace repose
