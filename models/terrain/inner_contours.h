#pragma once
// The contours between the key contours (seed paper 003, sec. 3-4): every
// key contour K shrinks by its straight skeleton; the polygon shrunk by d is
// the contour at height h_K + d * tan(slope) (the paper's constant-speed
// shrinking read as a ground of constant slope, the skeleton's "roof").
// Contours are made at the multiples of the contour interval; the skeleton's
// nodes give the ridge and summit points above the last contour.
//
// Nested key contours (an extension of the paper, which starts from one
// outer polygon): inside key contour K the ground is the higher of K's roof
// (rising inward) and the "skirt" of every key contour C nested in K
// (falling outward from C's height, by C's exterior skeleton). A contour
// level is the union of K's shrunk pieces and the children's grown outlines
// (CGAL Boolean union), so contours wrap around the inner key contours and
// meet them exactly. For the ground to pass through every key contour, the
// roof rises no faster than the lowest point of each child's outline allows
// and each skirt falls steeply enough to reach K's height before K or a
// sibling: the slopes start at slope_rad and are lowered (roof) or raised
// (skirt) only as far as the key contours demand. Concentric key contours
// that agree with slope_rad give a uniform slope (a cone from circles).
// Where a concave child's growing arms enclose a pocket, it is filled (no
// closed depressions).
//
// Every generated contour is then smoothed (bspline_contour.h) with a
// tolerance below 0.4 of its gap to every neighbouring contour and summit
// point, so smoothed contours never cross (the gaps follow from the roof
// being 1-Lipschitz: levels d apart are at least d apart in the plane).

#include <vector>

#include "models/terrain/key_contour.h"
#include "models/terrain/terrain_options.h"

namespace repose {

struct TerrainContour {
  Polygon2 polygon_m;   // sampled, counter-clockwise
  double height_m = 0.0;
  int key_index = 0;    // the key contour it is, or was shrunk from
  bool is_key = false;
  double smoothing_tolerance_m = 0.0;  // used (0 for key contours)
};

struct SummitPoint {
  Point2 point_m;
  double height_m = 0.0;
};

struct ContourSet {
  std::vector<TerrainContour> contours;
  std::vector<SummitPoint> summits;
};

// keys and nesting as validate_key_contours returned them.
ContourSet generate_contours(const std::vector<KeyContour>& keys, const ContourNesting& nesting,
                             const TerrainOptions& options);

}  // namespace repose
