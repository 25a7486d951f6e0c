#pragma once
// The volume a translating object sweeps between two poses (the ground
// paper, 3.3, Fig. 3): faces whose outward normal points along the motion
// are placed at the later pose, the others at the earlier pose, and every
// edge between a front and a back face (the silhouette), and every open
// edge, is extruded into a quad joining its two positions. Seen from below,
// the swept mesh's underside is the lowest the object reached between the
// poses, so one collision per frame leaves a continuous furrow.
//
// Only translation is swept: both poses use `to.orientation`; rotating
// objects are substepped by angle instead (ground_step.h).

#include "models/core/triangle_mesh.h"

namespace repose {

// body: in body coordinates. Returns world coordinates. When the two
// positions coincide, the body placed at `to`.
TriangleMesh swept_mesh(const TriangleMesh& body, const Pose& from, const Pose& to);

}  // namespace repose
