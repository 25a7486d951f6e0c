#pragma once
// The faces of a mesh that a view straight down or straight up sees from
// behind: the ground's underside renderer needs only the faces turned down,
// the height-span peeling the two halves separately.

#include "models/core/geometry/triangle_mesh.h"

namespace repose {

// The faces whose normal points down (turned_down) or up, on the same
// vertices; vertical faces are in neither (seen edge-on from above or below).
TriangleMesh faces_turned(const TriangleMesh& mesh, bool turned_down);

}  // namespace repose
