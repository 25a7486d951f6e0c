#include "validation/liggghts/liggghts_options.h"

#include <gtest/gtest.h>

#include <string>

#include "models/core/base/error.h"
#include "models/core/config/scene.h"
#include "models/core/config/scene_loader.h"
#include "tests/support/engine_section_checks.h"
#include "tests/validation/liggghts/dem_test_scene.h"
#include "validation/liggghts/liggghts_script.h"
#include "validation/liggghts/liggghts_section.h"
#include "validation/particles/dem_section.h"

namespace repose {
namespace {

Scene with_options(Scene scene, const LiggghtsOptions& options) {
  auto section = std::make_shared<LiggghtsSection>();
  section->options = options;
  scene.sections[LiggghtsSection::kKey] = section;
  return scene;
}

TEST(LiggghtsOptions, AbsentKeysKeepTheDocumentedDefaults) {
  const auto section = liggghts_section_type().read(parse_yaml("{sort_every_steps: 0}", "scene.yaml"), Scene{});
  const LiggghtsOptions& o = dynamic_cast<const LiggghtsSection&>(*section).options;
  EXPECT_EQ(o.sort_every_steps, 0);
  EXPECT_DOUBLE_EQ(o.neighbor_skin_radii, 1.0);
  EXPECT_EQ(o.neighbor_check_every_steps, 1);
}

TEST(LiggghtsOptions, MalformedSectionsGiveOneLineErrorsNamingTheKey) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"{neighbor_skin_radii: 0}", "neighbor_skin_radii"},
      {"{neighbor_skin_radii: nan}", "neighbor_skin_radii"},
      {"{neighbor_check_every_steps: 0}", "neighbor_check_every_steps"},
      {"{sort_every_steps: -1}", "sort_every_steps"},
      {"{sort_every_steps: 1.5}", "sort_every_steps"},
      {"{skin: 2}", "skin"},  // unknown key
  };
  test_support::expect_one_line_errors_naming_the_key(liggghts_section_type(), cases);
}

TEST(LiggghtsOptions, InASceneTheErrorNamesTheFileLineAndKeyPath) {
  test_support::expect_scene_error_names_file_line_and_key(
      liggghts_section_type(), "liggghts: {neighbor_check_every_steps: 5000}", "liggghts.neighbor_check_every_steps");
}

// The defaults write the lines every cached bed was made with; tuning
// changes the run script only, so a tuned run keeps its settled bed.
TEST(LiggghtsOptions, TuningChangesTheRunScriptAndNeverTheBed) {
  const Scene plain = testing::small_dem_scene(true);
  const std::string skin = liggghts_number(0.002 * 1.1);
  EXPECT_NE(bed_script(plain).find("neighbor " + skin + " bin\nneigh_modify delay 0\n\n#"), std::string::npos);
  const std::string plain_run = run_script(plain).text;
  EXPECT_NE(plain_run.find("neighbor " + skin + " bin\nneigh_modify delay 0\n\n#"), std::string::npos);
  EXPECT_EQ(plain_run.find("atom_modify sort"), std::string::npos);

  LiggghtsOptions tuned;
  tuned.neighbor_skin_radii = 0.5;
  tuned.neighbor_check_every_steps = 5;
  tuned.sort_every_steps = 0;
  const Scene fast = with_options(plain, tuned);
  EXPECT_EQ(bed_script(fast), bed_script(plain));
  const std::string run = run_script(fast).text;
  EXPECT_NE(run.find("neighbor " + liggghts_number(0.5 * 0.002 * 1.1) + " bin\n"), std::string::npos) << run;
  EXPECT_NE(run.find("neigh_modify delay 0 every 5 check yes\n"), std::string::npos) << run;
  EXPECT_NE(run.find("atom_modify sort 0 0\n"), std::string::npos) << run;
}

}  // namespace
}  // namespace repose
