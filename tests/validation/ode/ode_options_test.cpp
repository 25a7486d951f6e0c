#include "validation/ode/ode_options.h"

#include <gtest/gtest.h>

#include <string>

#include "models/core/base/error.h"

namespace repose {
namespace {

// The one-line error of reading `section` as a bullet: section.
std::string error_of(const std::string& section) {
  try {
    read_ode_options(parse_yaml(section, "scene.yaml"));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(OdeOptions, AbsentKeysKeepTheDocumentedDefaults) {
  const OdeOptions o = read_ode_options(parse_yaml("{solver_iterations: 15}", "scene.yaml"));
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

TEST(OdeOptions, ValidateNamesTheSectionAndTheField) {
  OdeOptions o;
  o.surface_layer_fraction = -1.0;
  try {
    validate(o);
    FAIL() << "accepted a negative slop";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("ode.surface_layer_fraction"), std::string::npos) << e.what();
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
