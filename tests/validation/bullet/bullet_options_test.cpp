#include "validation/bullet/bullet_options.h"

#include <gtest/gtest.h>

#include <string>

#include "models/core/base/error.h"

namespace repose {
namespace {

// The one-line error of reading `section` as a bullet: section.
std::string error_of(const std::string& section) {
  try {
    read_bullet_options(parse_yaml(section, "scene.yaml"));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(BulletOptions, AbsentKeysKeepTheDocumentedDefaults) {
  const BulletOptions o = read_bullet_options(parse_yaml("{solver_iterations: 15}", "scene.yaml"));
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
      {"[1, 2]", "time_step_s"},      // not a map: the allowed keys are listed
  };
  for (const auto& [section, key] : cases) {
    const std::string message = error_of(section);
    EXPECT_NE(message.find(key), std::string::npos) << section << " -> " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

TEST(BulletOptions, ValidateNamesTheSectionAndTheField) {
  BulletOptions o;
  o.linear_slop_fraction = -1.0;
  try {
    validate(o);
    FAIL() << "accepted a negative slop";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bullet.linear_slop_fraction"), std::string::npos) << e.what();
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
