#pragma once
// Which objects get a height-span map (DESIGN.md: only the modules a scene
// needs). An object holds material when the scene says so
// (heightspan.holds_material), else when its body is not convex: material
// can only stay on a convex body by lying on its top (a plate, a shovel),
// which a scene asks for by name; a convex body left on the ground model's
// path pushes material aside and never carries it.

#include "models/core/config/scene.h"
#include "models/core/geometry/triangle_mesh.h"

namespace repose {

// True when every vertex lies on or behind every face's plane (to 1e-9 of
// the mesh's size): a closed, outward-oriented mesh is then convex.
bool is_convex(const TriangleMesh& mesh);

// The rule above for one object of the scene.
bool holds_material(const Scene& scene, const ObjectSpec& object);

}  // namespace repose
