// The OSMesa path of the collision stage (collision.h): the object's
// underside rendered from below by OpenGL, as the ground paper does with
// graphics hardware. The depth range is the object's own z extent, padded so
// that no surface sits on the far plane (where it would count as not seen).

#include <algorithm>
#include <stdexcept>

#include "models/core/base/error.h"
#include "models/core/gl/osmesa_depth_renderer.h"
#include "models/ground/collision.h"

namespace repose {

namespace {

class OsmesaUndersideRenderer : public UndersideRenderer {
 public:
  std::string name() const override { return "osmesa"; }
  DepthImage render_below(const TriangleMesh& mesh, const Grid& sub, double z_min_m, double z_max_m) override {
    const double pad = std::max(1e-3, 0.01 * (z_max_m - z_min_m));
    return renderer_.render({mesh}, sub, ViewFrom::kBelow, DepthRange{z_min_m - pad, z_max_m + pad});
  }

 private:
  OsmesaDepthRenderer renderer_;
};

}  // namespace

std::unique_ptr<UndersideRenderer> make_osmesa_underside_renderer() {
  try {
    return std::make_unique<OsmesaUndersideRenderer>();
  } catch (const std::runtime_error& e) {
    throw InputError(std::string("ground_model.collision: osmesa: cannot start OpenGL: ") + e.what());
  }
}

}  // namespace repose
