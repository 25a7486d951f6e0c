#include "validation/liggghts_debris/liggghts_debris_script.h"

#include <map>
#include <utility>

#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "tests/validation/rigid/debris_test_world.h"

namespace repose {
namespace {

// The house with three elements: two of one material, one of another.
DebrisSetup two_materials() {
  DebrisSetup setup = test_support::house_on_flat_ground(1.0e6);
  setup.spec.elements.clear();
  for (int k = 0; k < 3; ++k) {
    DebrisElement e;
    e.centre_m = Eigen::Vector3d(-20.0 + 3 * k, -20, 1);
    e.friction = k == 2 ? 0.3 : 0.7;
    setup.spec.elements.push_back(e);
  }
  return setup;
}

std::string line_starting(const std::string& text, const std::string& start) {
  const auto at = text.find("\n" + start);
  if (at == std::string::npos) return "";
  return text.substr(at + 1, text.find('\n', at + 1) - at - 1);
}

TEST(LiggghtsDebrisScript, EachElementMaterialIsAnAtomTypeWithMeanPairValues) {
  const LiggghtsDebrisScript s = liggghts_debris_script(two_materials(), 1.0, {});
  EXPECT_EQ(s.atom_types, 3);  // walls, then the two materials
  // walls-walls: the building's 0.6; wall-element: the element's; between materials the mean
  EXPECT_EQ(line_starting(s.script, "fix m4"), "fix m4 all property/global coefficientFriction peratomtypepair 3 "
                                               "0.6 0.7 0.3 0.7 0.7 0.5 0.3 0.5 0.3");
  EXPECT_NE(s.data.find("\n3 0 0 0 0 0 0\n"), std::string::npos);  // the third atom at rest
  EXPECT_NE(s.data.find("\n3 3 1 2500 -14 -20 1\n"), std::string::npos);  // id type diameter density x y z
  EXPECT_EQ(s.meshes.size(), 1u + 4u);  // the terrain and the house's four parts
  EXPECT_EQ(s.total_steps, 1000);
}

// Closed (every edge in exactly two faces, once each way) and outward: the
// divergence theorem gives the prism's volume, positive.
TEST(LiggghtsDebrisScript, APartMeshIsAClosedOutwardPrism) {
  const DebrisSetup setup = test_support::house_on_flat_ground(1.0e6);
  for (const DebrisPart& part : setup.spec.parts) {
    const TriangleMesh m = part_mesh(part);
    std::map<std::pair<int, int>, int> edges;
    double volume = 0.0;
    for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
      for (int k = 0; k < 3; ++k) ++edges[{m.F(f, k), m.F(f, (k + 1) % 3)}];
      const Eigen::Vector3d a = m.V.row(m.F(f, 0)), b = m.V.row(m.F(f, 1)), c = m.V.row(m.F(f, 2));
      volume += a.dot(b.cross(c)) / 6.0;
    }
    for (const auto& [e, count] : edges) {
      EXPECT_EQ(count, 1);
      EXPECT_EQ(edges.count({e.second, e.first}), 1u);
    }
    const Eigen::Vector3d size = 2.0 * part.half_extents_m;
    EXPECT_GT(volume, 0.0);
    EXPECT_LE(volume, size.prod() * (1 + 1e-12));  // within its box
    EXPECT_NEAR(volume, part.mass_kg / 300.0, 1e-9 * volume);  // the house's bulk density
  }
}

TEST(LiggghtsDebrisScript, ARestitutionLiggghtsCannotTakeIsRefusedNamingIt) {
  DebrisSetup setup = two_materials();
  setup.spec.elements[0].restitution = 0.0;
  try {
    liggghts_debris_script(setup, 1.0, {});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("restitution"), std::string::npos) << e.what();
  }
}

TEST(LiggghtsDebrisScript, BadOptionsAreRefusedNamingTheField) {
  LiggghtsDebrisOptions o;
  o.time_step_s = 0.0;
  try {
    liggghts_debris_script(two_materials(), 1.0, o);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("time_step_s"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace repose
