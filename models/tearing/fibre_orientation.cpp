#include "models/tearing/fibre_orientation.h"

#include <cmath>
#include <numbers>

#include "models/core/base/error.h"

namespace repose {

FibreOrientation measure_fibre_orientation(const ArrayXXdR& image) {
  if (image.rows() < 3 || image.cols() < 3) throw InputError("fibre orientation: the image needs at least 3 x 3 pixels");
  double jxx = 0.0, jyy = 0.0, jxy = 0.0;
  for (Eigen::Index r = 1; r + 1 < image.rows(); ++r) {
    for (Eigen::Index c = 1; c + 1 < image.cols(); ++c) {
      const double gx = 0.5 * (image(r, c + 1) - image(r, c - 1));
      const double gy = 0.5 * (image(r + 1, c) - image(r - 1, c));
      jxx += gx * gx;
      jyy += gy * gy;
      jxy += gx * gy;
    }
  }
  FibreOrientation out;
  const double trace = jxx + jyy;
  if (trace <= 0.0) return out;  // a flat image: no direction, coherence 0
  // the gradient's principal direction, then turned a quarter to the fibres
  double angle = 0.5 * std::atan2(2.0 * jxy, jxx - jyy) + std::numbers::pi / 2;
  if (angle > std::numbers::pi / 2) angle -= std::numbers::pi;
  out.angle_rad = angle;
  out.coherence = std::hypot(jxx - jyy, 2.0 * jxy) / trace;
  return out;
}

}  // namespace repose
