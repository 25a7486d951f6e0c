#pragma once
// The height-span (HS) map of an object (the height-span paper, 2.1, Fig. 1):
// over a grid, per cell the ordered list of the object's solid vertical
// spans [bottom, top] along the vertical line through the cell centre, each
// with the height of granular material lying on its top.
//
// The spans come from depth peeling the object's closed mesh on the CPU:
// every triangle is rasterised over the cell centres it covers (a vertical
// ray per cell, as depth_image_cpu does), giving per cell the heights where
// the ray enters the body (faces turned down) and leaves it (faces turned
// up); a winding count over them, bottom to top, gives the solid spans, so
// a union of overlapping closed parts (a bucket merged from boxes) peels as
// its union. A centre on an edge shared by two triangles belongs to exactly
// one of them (the top-left rule of rasterisers, with the edge function
// evaluated the same way from both sides), so no hit is counted twice.
// Spans that touch merge; spans thinner than 1e-9 cell (a grazing ray) are
// dropped.
//
// The OSMesa path (osmesa_span_peeling.h) depth-peels the same mesh with
// OpenGL, as the paper does with graphics hardware, and builds the spans
// from its layers by the same rule (spans_from_hits); the two agree to the
// depth buffer's resolution (tested).
//
// Storage: compressed rows, cell c's spans are spans[first[c] .. first[c+1]),
// ordered bottom to top; cells are row-major over the grid (j outer).

#include <cstdint>
#include <vector>

#include "models/core/geometry/grid.h"
#include "models/core/geometry/triangle_mesh.h"

namespace repose {

struct Span {
  double bottom_m = 0.0;    // the solid's lower end (world z)
  double top_m = 0.0;       // its upper end
  double material_m = 0.0;  // height of material lying on top (>= 0)
  double level_m() const { return top_m + material_m; }
};

struct SpanMap {
  Grid grid;                       // world xy; for an object's map it moves with the object
  std::vector<std::int32_t> first; // cell_count + 1 offsets into spans
  std::vector<Span> spans;

  std::int64_t cell(int i, int j) const { return static_cast<std::int64_t>(j) * grid.nx + i; }
  int count(std::int64_t c) const { return first[c + 1] - first[c]; }
  Span* begin(std::int64_t c) { return spans.data() + first[c]; }
  const Span* begin(std::int64_t c) const { return spans.data() + first[c]; }
  bool empty() const { return spans.empty(); }
  // Material on all spans (m^3).
  double material_m3() const;
  // The cell whose area holds (x, y), or false when outside the grid.
  bool cell_at(double x_m, double y_m, int* i, int* j) const;
};

// The spans of a closed, outward-oriented mesh (world coordinates) over
// `grid`, with no material on them.
SpanMap peel_spans(const TriangleMesh& mesh, const Grid& grid);

// Where the vertical line through a cell's centre meets the body's surface.
struct SpanHit {
  std::int64_t cell;
  double z;
  int winding;  // +1 entering the body (a face turned down), -1 leaving it
};

// The spans (no material) from every cell's hits, in any order, by the
// winding rule above.
SpanMap spans_from_hits(std::vector<SpanHit> hits, const Grid& grid);

// Index (within its cell) of the highest span whose bottom is at or below
// z, -1 when none: the span a point at height z rests on or lies inside.
int span_under(const SpanMap& map, std::int64_t cell, double z_m);

// Moves material that rises above the bottom of the span over it onto that
// span's top (material never lies inside the object); returns how much was
// moved (m of height, summed). The topmost span takes any amount.
double push_overflow_up(SpanMap* map, std::int64_t cell);

}  // namespace repose
