#include "models/snow/snow_options.h"

#include <gtest/gtest.h>

#include <functional>

#include "models/core/base/error.h"

namespace repose {
namespace {

SnowOptions valid_options() {
  SnowOptions o;
  o.groups = {{"ground", true, {}}, {"table", false, {"top", "leg"}}};
  return o;
}

// The error text of validate() after `change`, "" when it passes.
std::string error_after(const std::function<void(SnowOptions*)>& change) {
  SnowOptions o = valid_options();
  change(&o);
  try {
    validate(o);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SnowOptions, ValidOptionsPass) { EXPECT_EQ(error_after([](SnowOptions*) {}), ""); }

TEST(SnowOptions, EachRuleNamesItsField) {
  const std::vector<std::pair<std::string, std::function<void(SnowOptions*)>>> cases = {
      {"groups: expected at least one group", [](SnowOptions* o) { o->groups.clear(); }},
      {"'ground' twice", [](SnowOptions* o) { o->groups[1].name = "ground"; }},
      {"no objects", [](SnowOptions* o) { o->groups[1].objects.clear(); }},
      {"the ground) without objects", [](SnowOptions* o) { o->groups[0].objects = {"x"}; }},
      {"at most one ground group", [](SnowOptions* o) { o->groups.push_back({"g2", true, {}}); }},
      {"direction_tilt_deg", [](SnowOptions* o) { o->main_direction.tilt_rad = 1.5; }},
      {"direction_count", [](SnowOptions* o) { o->direction_count = 0; }},
      {"cell_size_m", [](SnowOptions* o) { o->cell_size_m = -1.0; }},
      {"shadow_oversampling", [](SnowOptions* o) { o->shadow_oversampling = 0; }},
      {"shadow_bias_cells", [](SnowOptions* o) { o->shadow_bias_cells = -1.0; }},
      {"moved_fraction", [](SnowOptions* o) { o->moved_fraction = 0.26; }},
      {"moved_fraction", [](SnowOptions* o) { o->moved_fraction = 0.0; }},
      {"max_stabilisation_passes", [](SnowOptions* o) { o->max_stabilisation_passes = 0; }},
      {"settle_tolerance_m", [](SnowOptions* o) { o->settle_tolerance_m = 0.0; }},
  };
  for (const auto& [field, change] : cases) {
    const std::string err = error_after(change);
    EXPECT_NE(err.find(field), std::string::npos) << "expected '" << field << "' in: '" << err << "'";
  }
}

TEST(SnowOptions, MovedFractionLimitIsAccepted) {
  EXPECT_EQ(error_after([](SnowOptions* o) { o->moved_fraction = kSnowMovedFractionMax; }), "");
}

}  // namespace
}  // namespace repose
