#include "validation/ode/ode_debris_world.h"

#include <gtest/gtest.h>

#include "tests/validation/rigid/debris_test_world.h"

namespace repose {
namespace {

using namespace test_support;

std::unique_ptr<DebrisWorld> make_world(const DebrisWorldSpec& spec) { return make_ode_debris_world(spec, {}); }

TEST(OdeDebrisWorld, AnUntouchedHouseStandsForTheWholeRun) { expect_an_untouched_house_stands(make_world); }

TEST(OdeDebrisWorld, AHeavyFastBodyBreaksTheHouse) { expect_a_heavy_fast_body_breaks_the_house(make_world); }

TEST(OdeDebrisWorld, ASlowBodyLeavesAStrongHouseStanding) {
  expect_a_slow_body_leaves_a_strong_house_standing(make_world);
}

TEST(OdeDebrisWorld, AnElementRestingOnAPartWeighsOnIt) { expect_a_resting_element_weighs_on_its_part(make_world); }

TEST(OdeDebrisWorld, RollingResistanceStopsAHeavyElement) { expect_rolling_resistance_stops_a_heavy_element(make_world); }

}  // namespace
}  // namespace repose
