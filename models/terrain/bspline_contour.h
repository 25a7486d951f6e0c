#pragma once
// Smoothing a contour polygon with a closed uniform cubic B-spline (seed
// paper 003, sec. 4 step (7): the shrunk polygons have few vertices, so a
// B-spline through their vertices as control points shapes the ground).
//
// Departure from the paper, for a bound: the paper uses the polygon's
// vertices as the control points, which pulls the curve inward by up to a
// sixth of the corner's second difference, unbounded in the edge lengths,
// so neighbouring contours could cross. Here every corner V gets two extra
// control points on its edges at distance a <= tolerance from V, and long
// edges keep their end control points; each span of the curve lies in the
// convex hull of four consecutive control points, which lie on at most two
// adjacent edges within a of the corner, so the curve stays within
// `tolerance_m` of the polygon, and its sampled chords within 1.2 times it.
// Callers choose the tolerance below 0.4 of the gap to the neighbouring
// contours (0.48 with the chords), so smoothed contours never cross.

#include "models/terrain/polygon_2d.h"

namespace repose {

// The control points described above (closed sequence).
Polygon2 bspline_control_points(const Polygon2& polygon, double tolerance_m);

// Points on the closed uniform cubic B-spline of `control`: the curve is
// evaluated finely, then thinned so that every chord is at most spacing_m
// long and within max_deviation_m of the curve (points far closer than the
// spacing where the control points crowd would give the mesh slivers).
Polygon2 sample_closed_bspline(const Polygon2& control, double spacing_m, double max_deviation_m);

// Chords of a smoothed contour stay within this fraction of the tolerance
// of the curve, so the sampled contour lies within (1 + fraction) *
// tolerance_m of the polygon.
inline constexpr double kChordDeviationFraction = 0.2;

// Both steps: a smoothed, sampled contour within 1.2 tolerance_m of polygon.
Polygon2 smoothed_contour(const Polygon2& polygon, double tolerance_m, double spacing_m);

}  // namespace repose
