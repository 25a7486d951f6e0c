#pragma once
// The OSMesa path of the span maps (span_map.h): the object's faces turned
// down and its faces turned up are depth-peeled from below with OpenGL
// (models/core/gl/osmesa_depth_peeler.h), giving per cell every height where
// the vertical line enters and leaves the body; the spans follow by the same
// winding rule as the CPU path (spans_from_hits). Heights are quantised to
// the depth buffer's step over the mesh's z extent (2^-24 of it), and GL
// snaps vertices to 1/256 of a pixel, which moves a sloping face's height
// by up to slope * cell / 256: the two paths agree to that (tested), and
// span for span (same counts in every cell).

#include "models/core/gl/osmesa_depth_peeler.h"
#include "models/heightspan/span_map.h"

namespace repose {

SpanMap peel_spans_osmesa(const TriangleMesh& mesh, const Grid& grid, OsmesaDepthPeeler& peeler);

}  // namespace repose
