#include "validation/bullet/bullet_options.h"

#include <gtest/gtest.h>

#include <string>

#include "models/core/base/error.h"
#include "models/core/config/scene.h"
#include "models/core/config/scene_loader.h"
#include "validation/particles/dem_section.h"
#include "validation/bullet/bullet_section.h"

namespace repose {
namespace {

// The one-line error of reading `section` as a bullet: section.
std::string error_of(const std::string& section) {
  try {
    bullet_section_type().read(parse_yaml(section, "scene.yaml"), Scene{});
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

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
      {"[1, 2]", "time_step_s"},      // not a map: the allowed keys are listed
  };
  for (const auto& [section, key] : cases) {
    const std::string message = error_of(section);
    EXPECT_NE(message.find(key), std::string::npos) << section << " -> " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

TEST(BulletOptions, InASceneTheErrorNamesTheFileLineAndKeyPath) {
  const std::string scene =
      "time: {step_s: 0.01, duration_s: 0.1}\n"
      "ground: {extent_m: [0.04, 0.04], cell_size_m: 0.004, initial_height: {kind: flat, height_m: 0.01}}\n"
      "dem: {bed_depth_m: 0.01}\n"
      "bullet: {time_step_s: 0.5}\n";
  try {
    load_scene_from_string(scene, "/tmp/scene.yaml", {dem_section_type(), bullet_section_type()});
    FAIL() << "accepted a step of 0.5 s";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/tmp/scene.yaml:4:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("bullet.time_step_s"), std::string::npos) << e.what();
  }
  const Scene without = load_scene_from_string(scene.substr(0, scene.rfind("bullet:")), "/tmp/scene.yaml",
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
