#pragma once
// The contours between the key contours (seed paper 003, sec. 3-4): every
// key contour K shrinks by its straight skeleton; the polygon shrunk by d is
// the contour at height h_K + d * tan(slope) (the paper's constant-speed
// shrinking read as a ground of constant slope, the skeleton's "roof").
// Contours are made at the multiples of the contour interval; the skeleton's
// nodes give the ridge and summit points above the last contour.
//
// Nested key contours (an extension of the paper, which starts from one
// outer polygon): K's shrunk polygons stop where they would meet a key
// contour inside K (a "child"): a shrunk piece is dropped when it comes
// within a quarter of the level spacing of a child, lies inside one, lies
// in a dropped piece of a lower level, or encloses a child no higher than
// itself. Between the last kept piece and the child the mesh interpolates:
// where the key contours agree with the slope (concentric circles of a
// cone) the result is exact; where they do not, the ground between them is
// steeper or flatter than slope_rad, as the key contours demand.
//
// Every generated contour is then smoothed (bspline_contour.h) with a
// tolerance below 0.45 of its gap to every neighbouring contour and summit
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
  int dropped_pieces = 0;  // shrunk pieces dropped near nested key contours
};

// keys and nesting as validate_key_contours returned them.
ContourSet generate_contours(const std::vector<KeyContour>& keys, const ContourNesting& nesting,
                             const TerrainOptions& options);

}  // namespace repose
