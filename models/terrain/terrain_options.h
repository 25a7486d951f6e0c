#pragma once
// How the terrain is generated from its key contours (seed paper 003,
// sec. 3-4). Lengths in metres, angles in radians (degrees only in files).

namespace repose {

struct TerrainOptions {
  // Height between generated contours; contour levels are the multiples of
  // this between a key contour's height and the summit above it.
  double contour_interval_m = 1.0;
  // Slope of the ground rising inward from a key contour: shrinking a
  // contour by d raises it by d * tan(slope_rad) (the straight-skeleton
  // "roof"; the paper's constant-speed shrinking).
  double slope_rad = 0.5235987755982988;  // 30 degrees
  // Largest distance a smoothed (B-spline) contour may lie from its polygon;
  // lowered per contour to keep neighbouring contours from crossing.
  double smoothing_tolerance_m = 0.5;
  // Longest edge of the sampled contours (and of densified key contours):
  // the size of the mesh's triangles along the contours.
  double sample_spacing_m = 1.0;
  // Cell size of the height field sampled from the mesh.
  double cell_size_m = 1.0;

  // Throws FieldError (an InputError) naming the scene key and the rule:
  // every length > 0 and finite, slope_deg in (0, 90).
  void validate() const;
};

}  // namespace repose
