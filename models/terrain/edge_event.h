#pragma once
// Seed paper 003, sec. 3.2, eq. (1): while a polygon shrinks (every edge
// moving inward at unit speed) and no split event happens first, edge i
// vanishes at the shrink distance
//   e_d_shri = L_i / (cot(theta_i / 2) + cot(theta_{i+1} / 2))
// with L_i its length and theta_i, theta_{i+1} the interior angles at its two
// ends. It applies only when the two bisectors meet inside the polygon,
// 0.5 theta_i + 0.5 theta_{i+1} < 180 deg; otherwise the edge grows.
// The smallest of these over all edges is the first edge event (step (2)
// of sec. 4). The tests check it against CGAL's skeleton (straight_skeleton.h).

#include "models/terrain/polygon_2d.h"

namespace repose {

// Interior angle (rad, in (0, 2 pi)) at vertex i of a counter-clockwise polygon.
double interior_angle_rad(const Polygon2& polygon, std::size_t i);

// eq. (1) for the edge from vertex i to vertex i+1 of a counter-clockwise
// polygon; +infinity when the edge does not shrink to a point.
double edge_vanish_distance_m(const Polygon2& polygon, std::size_t i);

// The smallest eq. (1) distance over all edges (+infinity if none shrinks).
double first_edge_event_distance_m(const Polygon2& polygon);

}  // namespace repose
