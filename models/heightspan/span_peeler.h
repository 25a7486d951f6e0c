#pragma once
// Who peels an object's span map (span_map.h): the CPU path (peel_spans) or
// the OSMesa path (osmesa_span_peeling.h), as heightspan.span_maps says.
// The OSMesa peeler owns a GL context, bound to the thread that made it.

#include <memory>
#include <string>

#include "models/heightspan/span_map.h"

namespace repose {

class SpanPeeler {
 public:
  virtual ~SpanPeeler() = default;
  virtual std::string name() const = 0;  // "cpu" or "osmesa"
  virtual SpanMap peel(const TriangleMesh& mesh, const Grid& grid) = 0;
};

std::unique_ptr<SpanPeeler> make_cpu_span_peeler();
// Throws InputError when OpenGL (and its shaders) cannot be started through OSMesa.
std::unique_ptr<SpanPeeler> make_osmesa_span_peeler();

}  // namespace repose
