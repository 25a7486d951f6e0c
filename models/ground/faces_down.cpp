#include "models/ground/faces_down.h"

#include "models/core/geometry/faces_turned.h"

namespace repose {

FacesDown faces_down_of(const TriangleMesh& mesh) { return FacesDown{faces_turned(mesh, true), bounding_box(mesh)}; }

}  // namespace repose
