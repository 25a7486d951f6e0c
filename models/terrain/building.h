#pragma once
// Buildings made of parts that can come apart (seed paper 003, sec. 4-5: a
// dynamic 3-D building model whose members are convex solids, separated so
// that they do not overlap and spring apart at the start). A footprint is
// split into convex pieces (convex_partition.h), each extruded per storey
// into a convex prism; storeys are stacked with a small gap.
//
// Not done here (see the report): walls, floors and roof plates as separate
// members, window openings, and the breakable joints that hold the parts
// together belong to the rigid-body engines (Bullet/ODE), not to this layout.

#include <string>
#include <vector>

#include "models/core/geometry/triangle_mesh.h"
#include "models/terrain/terrain_surface.h"

namespace repose {

struct BuildingFootprint {
  std::string name;
  Polygon2 polygon_m;           // simple, either orientation
  int storeys = 1;
  double storey_height_m = 3.0;
  double gap_m = 0.01;          // between stacked storeys
  // For the rigid-body engines (validation/rigid/debris_world.h): the mass
  // per volume of its parts (a building is mostly air: ~300 kg/m^3 for a
  // house, where concrete is 2,400), and the force (N) above which a joint
  // holding two parts (or a bottom part to the ground) breaks. A joint
  // carries the weight of what stands on it, so this must exceed the weight
  // of the storeys above the ground floor (debris_setup.h reports it).
  double bulk_density_kg_m3 = 300.0;
  double joint_break_force_n = 1.0e7;

  // Throws InputError naming the building: a simple polygon of >= 3
  // vertices, storeys >= 1, storey_height_m > 0, gap_m in [0, storey_height_m),
  // bulk_density_kg_m3 > 0, joint_break_force_n > 0.
  void validate() const;
};

struct BuildingPart {
  Polygon2 footprint_m;   // convex, counter-clockwise
  double bottom_m = 0.0;
  double top_m = 0.0;
  int storey = 0;
  int piece = 0;          // index of the convex piece of the footprint
  int building = 0;       // index of its footprint in the scene (generate_scenery)
};

// The parts of one building standing on `surface`: the base is the highest
// terrain point under the footprint, so no part cuts into the ground.
// Throws InputError when the footprint is not entirely over the terrain.
std::vector<BuildingPart> building_parts(const BuildingFootprint& footprint, const TerrainSurface& surface);

// Highest point (m) of the surface over a polygon (exact for a piecewise
// linear surface: at the polygon's vertices, the mesh vertices inside it or
// where its edges cross mesh edges); nullopt if some of it has no terrain.
std::optional<double> highest_ground_m(const TerrainSurface& surface, const Polygon2& polygon);

// A closed convex prism, outward faces.
TriangleMesh prism_mesh(const Polygon2& convex_ccw, double bottom_m, double top_m);

}  // namespace repose
