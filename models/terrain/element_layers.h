#pragma once
// Moving elements laid on the terrain in layers (seed paper 003, sec. 4 and
// fig. 4: spheres placed on the Delaunay triangles, their shape, friction
// and bounciness changed by layer to build strata, "placed so that they do
// not overlap horizontally or vertically", since overlapping elements would
// spring apart at the start).
//
// Departure from the paper: the paper computes positions inside each
// triangle (points dividing its edges); here each layer is a square lattice
// over the source region (offset by half a spacing on odd rows so rows
// nest), and each sphere is lowered vertically until it touches the terrain
// or a sphere of an earlier row. Lattice spacing 2 r (1 + gap) keeps a row
// apart; lowering keeps rows apart; so no two elements overlap by
// construction, and the first row rests on the surface.
//
// A random bed (the scene's seed): with radius_spread > 0 each sphere's
// radius is drawn uniformly in [r (1 - radius_spread), r] (r: its layer's
// radius_m), and with position_jitter > 0 its lattice point is moved in a
// uniform random direction by up to position_jitter times its room,
// (r - r_i) + gap_fraction r / 2. Two row neighbours moved that far are still
// r_i + r_j + gap_fraction r apart (the lattice spacing is 2 r (1 + gap)), so
// the layout keeps its no-overlap construction. Both 0 (the defaults): the
// seed is not used and the lattice is regular.

#include <cstdint>
#include <string>
#include <vector>

#include "models/terrain/terrain_surface.h"

namespace repose {

struct ElementLayer {
  std::string name;
  double radius_m = 0.5;
  int rows = 1;               // rows of spheres stacked in this layer
  double friction = 0.5;      // Coulomb coefficient, >= 0
  double restitution = 0.2;   // in [0, 1]
  double density_kg_m3 = 2500.0;  // solid rock; the rigid-body engines' element mass
  // Rolling resistance mu_r (a torque of at most mu_r r_eff N, rigid_world.h):
  // the rigid engines' stand-in for angular rocks, which do not roll freely.
  double rolling_friction = 0.1;
};

struct ElementSource {
  Polygon2 region_m;                  // where the elements lie (xy), simple
  std::vector<ElementLayer> layers;   // bottom layer first
  double gap_fraction = 0.01;         // clearance between elements, times the smaller radius
  double radius_spread = 0.0;         // radii uniform in [r (1 - spread), r]; in [0, 1)
  double position_jitter = 0.0;       // fraction of each sphere's room it is moved by at most; in [0, 1]
  std::uint64_t seed = 1;             // the random bed's generator (the scene's seed, terrain_section.h)

  // Throws InputError naming the field: a simple region of >= 3 vertices,
  // at least one layer, radius_m > 0, rows >= 1, friction >= 0, restitution
  // in [0, 1], density_kg_m3 > 0, rolling_friction >= 0, gap_fraction in
  // [0, 1), radius_spread in [0, 1), position_jitter in [0, 1].
  void validate() const;
};

struct PlacedElement {
  Eigen::Vector3d centre_m;
  double radius_m = 0.0;
  int layer = 0;  // index into ElementSource::layers
};

struct ElementLayout {
  std::vector<PlacedElement> elements;
  int skipped_off_terrain = 0;  // lattice points with no terrain below
};

// Deterministic: the lattice is anchored at the region's bounding-box corner,
// and the random bed is drawn from std::mt19937_64(source.seed), one radius
// and one displacement per lattice point in row order.
ElementLayout place_element_layers(const TerrainSurface& surface, const ElementSource& source);

}  // namespace repose
