#pragma once
// The lowest height at which a sphere above a given horizontal position
// clears a triangle mesh that is a height field: the sphere is lowered
// vertically onto the surface until it touches a face, an edge or a vertex.

#include "models/terrain/terrain_surface.h"

namespace repose {

// Centre height (m) of a sphere of radius_m at xy resting on `surface`;
// nullopt when the surface has no face within radius_m of xy horizontally.
std::optional<double> sphere_rest_height_m(const TerrainSurface& surface, const Point2& xy, double radius_m);

// The same against one sphere below (centre, radius): the lowest centre
// height that keeps the two apart by gap_m; nullopt when they do not overlap
// horizontally.
std::optional<double> sphere_on_sphere_height_m(const Point2& xy, double radius_m, const Eigen::Vector3d& below_m,
                                                double below_radius_m, double gap_m);

}  // namespace repose
