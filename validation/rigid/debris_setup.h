#pragma once
// A terrain scene (models/terrain, the scene's terrain: section) as a
// debris world for the rigid-body engines (debris_world.h): the generated
// terrain mesh, the placed elements with their layers' values, each
// building part as a convex prism of the building's bulk density, and the
// joints that hold a building together:
//   - parts of one storey whose footprints touch (convex pieces of one
//     footprint), anchored halfway between their centres;
//   - a part and the one above it (same piece, next storey), anchored at the
//     middle of the gap between them;
//   - a ground-floor part and the ground, anchored at its base centre;
// every joint of a building breaking above its joint_break_force_n.
// The parts start kPartClearanceM above the ground (held there by the
// ground joints): Bullet's collision margins of the terrain and a hull
// overlapped at the highest ground point, and that contact pushing against
// the ground joint gave 1.2e9 N on a 64 t barn in the first step.

#include <string>
#include <vector>

#include "models/terrain/terrain_scene.h"
#include "validation/rigid/debris_world.h"

namespace repose {

inline constexpr double kPartClearanceM = 0.1;

struct DebrisSetup {
  TerrainScenery scenery;
  DebrisWorldSpec spec;
  std::vector<std::string> building_names;  // scene order
  std::vector<int> joint_building;          // per joint: its building
  Eigen::Vector2d flow_direction = Eigen::Vector2d(1, 0);  // downhill at the source (unit, xy)
  Eigen::Vector2d source_centre_m = Eigen::Vector2d::Zero();
};

// Throws InputError (one line naming the field) for an invalid scene, and
// for a scene without elements (terrain: elements). Every layer's
// rolling_friction is multiplied by rolling_friction_scale (a fit's handle).
DebrisSetup debris_setup(const TerrainScene& scene, const DebrisMaterial& material, double rolling_friction_scale = 1.0);

// Appends one building (its parts from building_parts(), lifted by
// kPartClearanceM) to setup: a name, parts and joints (its index: the
// number of buildings before it).
void append_building(const BuildingFootprint& footprint, std::vector<BuildingPart> parts, DebrisSetup& setup);

// The joints of one building's parts (all of `parts` belong to it).
std::vector<DebrisJoint> building_joints(const std::vector<BuildingPart>& parts, const std::vector<int>& part_index,
                                         double break_force_n);

// A building part as a convex body of the given bulk density.
DebrisPart debris_part(const BuildingPart& part, double bulk_density_kg_m3);

// The closest distance (m) between two elements' surfaces over all pairs
// (negative: they overlap); +infinity for fewer than two. O(n^2 / buckets).
double min_element_clearance_m(const std::vector<DebrisElement>& elements);

}  // namespace repose
