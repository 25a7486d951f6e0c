#pragma once
// Key contours: the few closed contour polygons, each with its height, from
// which the terrain is generated (seed paper 003, sec. 4: the "key contour
// (outer polygon)" drawn on a GIS map). Contours nest: a contour inside
// another is higher (a rise) and no two contours meet.
//
// Departure from the paper: the paper starts from one outer polygon per
// rise; here several key contours may nest, and each inner key contour is a
// height the terrain must pass through (see inner_contours.h for how the
// contours between a key contour and the key contours inside it are made).

#include <string>
#include <vector>

#include "models/terrain/polygon_2d.h"

namespace repose {

struct KeyContour {
  std::string name;     // for error messages and outputs
  Polygon2 polygon_m;   // closed, simple; either orientation on input
  double height_m = 0.0;
};

// The nesting of a validated set: parent[i] is the index of the smallest key
// contour containing contour i, or -1 for an outermost one.
struct ContourNesting {
  std::vector<int> parent;
  std::vector<std::vector<int>> children;
  std::vector<int> roots;
};

// Checks a set of key contours and returns their nesting; the polygons are
// made counter-clockwise. Throws InputError with one line naming the contour
// when: fewer than 3 vertices, a non-finite coordinate or height, the polygon
// intersects itself, two contours' boundaries meet, or a contour is not
// higher than the contour it lies in.
ContourNesting validate_key_contours(std::vector<KeyContour>* contours);

}  // namespace repose
