#include "models/heightspan/osmesa_span_peeling.h"

#include <algorithm>

#include "models/core/geometry/faces_turned.h"

namespace repose {

SpanMap peel_spans_osmesa(const TriangleMesh& mesh, const Grid& grid, OsmesaDepthPeeler& peeler) {
  std::vector<SpanHit> hits;
  if (!mesh.empty()) {
    const Aabb box = bounding_box(mesh);
    const double pad = std::max(1e-3, 0.01 * (box.max.z() - box.min.z()));
    const DepthRange range{box.min.z() - pad, box.max.z() + pad};
    for (const bool down : {true, false}) {
      const DepthLayers layers = peeler.peel_from_below(faces_turned(mesh, down), grid, range);
      for (std::size_t c = 0; c < layers.z_m.size(); ++c) {
        for (const double z : layers.z_m[c]) hits.push_back({static_cast<std::int64_t>(c), z, down ? +1 : -1});
      }
    }
  }
  return spans_from_hits(std::move(hits), grid);
}

}  // namespace repose
