#include "models/heightspan/osmesa_span_peeling.h"

#include <algorithm>

namespace repose {

namespace {

// The faces whose normal points down (turned_down) or up; vertical faces are seen edge-on by neither.
TriangleMesh faces_turned(const TriangleMesh& mesh, bool turned_down) {
  TriangleMesh out;
  out.V = mesh.V;
  out.F.resize(mesh.F.rows(), 3);
  Eigen::Index n = 0;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)), c = mesh.V.row(mesh.F(f, 2));
    const double nz = (b - a).cross(c - a).z();
    if (turned_down ? nz < 0.0 : nz > 0.0) out.F.row(n++) = mesh.F.row(f);
  }
  out.F.conservativeResize(n, 3);
  return out;
}

}  // namespace

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
