#include "models/terrain/key_contour.h"

#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "tests/models/terrain/terrain_fixtures.h"

namespace repose {
namespace {

std::string error_of(std::vector<KeyContour> contours) {
  try {
    validate_key_contours(&contours);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(KeyContour, NestingFindsTheSmallestParent) {
  std::vector<KeyContour> cs = {{"base", test::rectangle_polygon(0, 0, 100, 100), 0.0},
                                {"peak a", test::circle_polygon(Point2(30, 50), 10, 12), 20.0},
                                {"ridge", test::rectangle_polygon(10, 10, 90, 90), 10.0},
                                {"peak b", test::circle_polygon(Point2(70, 50), 10, 12), 25.0}};
  const ContourNesting n = validate_key_contours(&cs);
  EXPECT_EQ(n.roots, std::vector<int>({0}));
  EXPECT_EQ(n.parent, std::vector<int>({-1, 2, 0, 2}));
  EXPECT_EQ(n.children[2], std::vector<int>({1, 3}));
}

TEST(KeyContour, ClockwiseInputIsTurned) {
  Polygon2 cw = test::rectangle_polygon(0, 0, 1, 1);
  std::reverse(cw.begin(), cw.end());
  std::vector<KeyContour> cs = {{"a", cw, 0.0}};
  validate_key_contours(&cs);
  EXPECT_GT(signed_area_m2(cs[0].polygon_m), 0.0);
}

TEST(KeyContour, MalformedContoursGiveOneLineNamingTheContour) {
  const Polygon2 bow_tie = {Point2(0, 0), Point2(1, 1), Point2(1, 0), Point2(0, 1)};
  const std::string self = error_of({{"bow", bow_tie, 0.0}});
  EXPECT_NE(self.find("'bow'"), std::string::npos) << self;
  EXPECT_NE(self.find("intersects itself"), std::string::npos) << self;

  const std::string crossing = error_of({{"a", test::rectangle_polygon(0, 0, 2, 2), 0.0},
                                         {"b", test::rectangle_polygon(1, 1, 3, 3), 5.0}});
  EXPECT_NE(crossing.find("'a'"), std::string::npos) << crossing;
  EXPECT_NE(crossing.find("must nest"), std::string::npos) << crossing;

  const std::string lower = error_of({{"outer", test::rectangle_polygon(0, 0, 10, 10), 5.0},
                                      {"inner", test::rectangle_polygon(2, 2, 4, 4), 5.0}});
  EXPECT_NE(lower.find("'inner'"), std::string::npos) << lower;
  EXPECT_NE(lower.find("increase inward"), std::string::npos) << lower;

  const std::string few = error_of({{"line", {Point2(0, 0), Point2(1, 0)}, 0.0}});
  EXPECT_NE(few.find("'line'"), std::string::npos) << few;
  for (const std::string& e : {self, crossing, lower, few}) EXPECT_EQ(e.find('\n'), std::string::npos);
}

}  // namespace
}  // namespace repose
