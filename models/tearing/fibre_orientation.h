#pragma once
// The mean fibre orientation of a density image, measured by its structure
// tensor J = sum over pixels of grad(d) grad(d)^T (central differences,
// interior pixels). Density changes fastest across fibres, so J's leading
// eigenvector is normal to the fibres and the orientation is 90 degrees
// from it. Coherence (l1 - l2) / (l1 + l2) is 0 for no preferred direction
// and 1 for perfectly parallel fibres.

#include "models/core/geometry/height_field.h"

namespace repose {

struct FibreOrientation {
  double angle_rad = 0.0;  // in (-pi/2, pi/2], from +x towards +y
  double coherence = 0.0;  // in [0, 1]
};

// image: ny x nx, row 0 at the smallest y; at least 3 x 3 pixels.
FibreOrientation measure_fibre_orientation(const ArrayXXdR& image);

}  // namespace repose
