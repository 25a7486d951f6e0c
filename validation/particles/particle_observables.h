#pragma once
// Observables of a granular state shared by the DEM references and the
// heuristics, so the two can be compared cell by cell (SI units, radians):
//   material per unit area on the grid, the mass of grains in a box or held
//   by an object, the runout front along a direction, the flank angles of a pile.
// The surface height field itself is in surface_height.h.

#include <numbers>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "models/core/geometry/grid.h"
#include "models/core/geometry/height_field.h"
#include "models/core/geometry/triangle_mesh.h"
#include "validation/particles/grain_set.h"

namespace repose {

// Grain volume per unit area (m): the volume of each grain is given to the
// cell holding its centre, divided by the cell area. Grains outside the grid
// are left out. Divide by a packing fraction to compare with heights.
HeightField material_per_area(const GrainSet& grains, const Grid& grid);
// The same divided by packing_fraction (0, 1]: the height of bulk material
// holding that much grain volume.
HeightField equivalent_height(const GrainSet& grains, const Grid& grid, double packing_fraction);

// Mass (kg) of the grains whose centre lies inside the box, all of density density_kg_m3.
double mass_in_box_kg(const GrainSet& grains, const Aabb& box, double density_kg_m3);
// Total grain volume (m^3).
double grain_volume_m3(const GrainSet& grains);

// Mass (kg) of the grains held by an object, all of density density_kg_m3.
// object_world is the object's triangle mesh in world coordinates (faces
// counter-clockwise seen from outside; it may be a union of overlapping
// closed parts, e.g. a bucket `merged` from a floor box and four wall boxes).
// A grain is held when its centre c
//   (a) lies inside the mesh: the generalised winding number of the mesh
//       about c exceeds 1/2 (for overlapping closed parts it counts the
//       parts holding c), or
//   (b) lies in the object's open-top hull: c.z is at most the top of the
//       mesh (its bounding box's max z) and the vertical ray from c
//       downwards meets an upward-facing face (outward normal with z > 0)
//       at or below c.z: the grain is above the object's floor and below its rim.
// So grains inside a bucket are held, grains beside it, under it or above
// its rim are not. Grains resting on a flat plate or on top of a closed body
// lie above its top and are not held (the rule is for containers). Grains
// are counted by centre; an empty mesh holds nothing.
double mass_held_by_object_kg(const GrainSet& grains, const TriangleMesh& object_world, double density_kg_m3);

// The runout front: the `quantile` (default 0.99) of the grains' distances
// along `direction` (normalised here) from `origin_m`. Grains behind the
// origin count with negative distances. Throws InputError for no grains.
double front_position_m(const GrainSet& grains, const Eigen::Vector3d& origin_m, const Eigen::Vector3d& direction,
                        double quantile = 0.99);

// The front of a deposit, leaving out grains thrown ahead of it: the grains'
// centre distances along `direction` (normalised here) from origin_m are
// sorted; walking out from the nearest, the deposit ends at the first gap
// between consecutive distances larger than max_gap_m; the front is the
// farthest outer edge (distance + radius) reached before it. Throws
// InputError for no grains or a non-positive gap.
double deposit_front_m(const GrainSet& grains, const Eigen::Vector3d& origin_m, const Eigen::Vector3d& direction,
                       double max_gap_m);

struct RadialFront {
  std::vector<double> sector_front_m;  // per azimuth sector that holds grains
  double mean_m = 0.0;
  double std_m = 0.0;                  // sample standard deviation over the sectors (0 for one)
};

// The azimuths, from the +x axis, that a radial front is measured over:
// all of them by default, [0, pi/2] for a quarter column between its walls.
struct AzimuthRange {
  double begin_rad = -std::numbers::pi;
  double span_rad = 2.0 * std::numbers::pi;
};

// The same rule radially, per azimuth sector (sector_count equal sectors of
// the azimuth range around the vertical axis through axis_xy_m; a grain
// outside the range counts in the nearer end sector): distances in the xy
// plane from the axis. For the runout of an axisymmetric collapse.
RadialFront radial_deposit_front(const GrainSet& grains, const Eigen::Vector2d& axis_xy_m, double max_gap_m,
                                 int sector_count = 16, const AzimuthRange& range = {});

// The top of the grains: the largest z + radius (m). InputError for no grains.
double grain_top_m(const GrainSet& grains);

struct FlankAngleOptions {
  int azimuth_count = 16;       // rays from the centre, evenly spaced
  double lower_fraction = 0.2;  // flank: heights between these fractions of the peak height
  double upper_fraction = 0.8;
  int min_samples = 3;          // rays with fewer flank samples are left out
};

struct FlankAngles {
  std::vector<double> azimuth_rad;  // of the rays that had a flank
  std::vector<double> angle_rad;    // atan(-slope) of the line fitted to height against distance
  double mean_rad = 0.0;
  double std_rad = 0.0;             // sample standard deviation over the rays (0 for one ray)
};

// Pile flank angles: along each ray from centre (x, y) the height field is
// sampled (bilinear) every half cell out to the grid's edge; samples whose
// height lies between the fractions of the peak (the highest sample of all
// rays) are fitted by least squares. Throws InputError when no ray has a flank.
FlankAngles pile_flank_angles(const HeightField& height, const Eigen::Vector2d& centre_m,
                              const FlankAngleOptions& options = {});

// CSV of a field on its grid: a header "x_m,y_m,value" then one row per cell
// (row-major, j outer), values printed round-trip exact.
void write_field_csv(const std::string& path, const HeightField& field, const std::string& value_name);
void write_flank_angles_csv(const std::string& path, const FlankAngles& angles);

}  // namespace repose
