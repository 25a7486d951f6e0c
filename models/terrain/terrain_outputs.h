#pragma once
// Writing a generated terrain for analysis and viewing: the mesh (OBJ and
// PLY), the sampled height field and the contours (.npy), the moving
// elements and building parts when there are any.

#include <string>
#include <vector>

#include "models/terrain/building.h"
#include "models/terrain/element_layers.h"
#include "models/terrain/terrain.h"

namespace repose {

// Files written into `directory` (which must exist), returned as names:
//   terrain_mesh.obj, terrain_mesh.ply   the triangle mesh
//   terrain_height.npy                   height field, ny x nx (row 0 = smallest y)
//   contours.npy                         one row per contour point: contour index, x, y, z, is_key
//   summits.npy                          skeleton summit points: x, y, z (when there are any)
//   elements.npy                         x, y, z, radius, layer (when there are elements)
//   buildings.obj                        all building parts as closed prisms (when there are parts)
std::vector<std::string> write_terrain_outputs(const std::string& directory, const Terrain& terrain,
                                               const std::vector<PlacedElement>& elements,
                                               const std::vector<BuildingPart>& parts);

}  // namespace repose
