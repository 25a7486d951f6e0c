#include "models/heightspan/span_peeler.h"

#include <stdexcept>

#include "models/core/base/error.h"
#include "models/heightspan/osmesa_span_peeling.h"

namespace repose {

namespace {

class CpuSpanPeeler final : public SpanPeeler {
 public:
  std::string name() const override { return "cpu"; }
  SpanMap peel(const TriangleMesh& mesh, const Grid& grid) override { return peel_spans(mesh, grid); }
};

class OsmesaSpanPeeler final : public SpanPeeler {
 public:
  std::string name() const override { return "osmesa"; }
  SpanMap peel(const TriangleMesh& mesh, const Grid& grid) override { return peel_spans_osmesa(mesh, grid, peeler_); }

 private:
  OsmesaDepthPeeler peeler_;
};

}  // namespace

std::unique_ptr<SpanPeeler> make_cpu_span_peeler() { return std::make_unique<CpuSpanPeeler>(); }

std::unique_ptr<SpanPeeler> make_osmesa_span_peeler() {
  try {
    return std::make_unique<OsmesaSpanPeeler>();
  } catch (const std::runtime_error& e) {
    throw InputError(std::string("heightspan.span_maps: osmesa: cannot start OpenGL: ") + e.what());
  }
}

}  // namespace repose
