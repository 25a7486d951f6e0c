#pragma once
// What collision looks at of an object in one (sub)step: its faces turned
// down (the only ones a view from below sees, collision.h), with the
// bounding box of the whole placed or swept mesh they were taken from. The
// box sets the footprint and the contact test, so it is the whole mesh's
// (as when all vertices are kept), while the mesh may keep only the
// vertices its faces use: fewer vertices to bound and to rasterise.

#include "models/core/geometry/triangle_mesh.h"

namespace repose {

struct FacesDown {
  TriangleMesh mesh;  // faces turned down (normal z < 0), on the vertices they use or more
  Aabb box;           // bounding box of the whole mesh they came from
};

// faces_turned(mesh, true) with the mesh's bounding box.
FacesDown faces_down_of(const TriangleMesh& mesh);

}  // namespace repose
