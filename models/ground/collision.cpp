#include "models/ground/collision.h"

#include <algorithm>
#include <cmath>

#include "models/core/geometry/faces_turned.h"

namespace repose {

Grid Footprint::sub_grid(const Grid& grid) const {
  Grid g = grid;
  g.nx = ni;
  g.ny = nj;
  g.origin_x_m = grid.origin_x_m + i0 * grid.cell_size_m;
  g.origin_y_m = grid.origin_y_m + j0 * grid.cell_size_m;
  return g;
}

Footprint footprint_of(const Aabb& box, const Grid& grid) {
  if (box.empty()) return {};
  const double h = grid.cell_size_m;
  // cell centres inside [min, max], give or take 1e-9 cell: a box edge on a
  // row of centres (a sphere of radius 5 cm on 4 mm cells) then takes that
  // row on both sides alike, not as round-off decides (a footprint one row
  // wider on one side made drags lopsided); clamped to the grid
  constexpr double kTie = 1e-9;
  const double fi0 = std::ceil((box.min.x() - grid.origin_x_m) / h - 0.5 - kTie);
  const double fi1 = std::floor((box.max.x() - grid.origin_x_m) / h - 0.5 + kTie);
  const double fj0 = std::ceil((box.min.y() - grid.origin_y_m) / h - 0.5 - kTie);
  const double fj1 = std::floor((box.max.y() - grid.origin_y_m) / h - 0.5 + kTie);
  const int i0 = static_cast<int>(std::clamp(fi0, 0.0, static_cast<double>(grid.nx)));
  const int i1 = static_cast<int>(std::clamp(fi1, -1.0, static_cast<double>(grid.nx - 1)));
  const int j0 = static_cast<int>(std::clamp(fj0, 0.0, static_cast<double>(grid.ny)));
  const int j1 = static_cast<int>(std::clamp(fj1, -1.0, static_cast<double>(grid.ny - 1)));
  if (i1 < i0 || j1 < j0) return {};
  return Footprint{i0, j0, i1 - i0 + 1, j1 - j0 + 1};
}

namespace {

class CpuUndersideRenderer : public UndersideRenderer {
 public:
  std::string name() const override { return "cpu"; }
  DepthImage render_below(const TriangleMesh& mesh, const Grid& sub, double, double) override {
    return cache_.render(mesh, sub, ViewFrom::kBelow);
  }

 private:
  DepthImageCpuCache cache_;  // a body pressed straight down is drawn again from its last coverage
};

}  // namespace

std::unique_ptr<UndersideRenderer> make_cpu_underside_renderer() { return std::make_unique<CpuUndersideRenderer>(); }

Underside find_underside(const TriangleMesh& mesh, const HeightField& ground, UndersideRenderer& renderer,
                         int reach_cells) {
  // Seen from below, the lowest point of a closed, outward-oriented mesh over a
  // cell lies on a face turned downwards (where a vertical line enters the
  // body), so only those faces need rendering: about half of them.
  return find_underside_of_faces_down(faces_turned(mesh, true), ground, renderer, reach_cells);
}

namespace {

Underside underside_in_box(const TriangleMesh& faces_down, const Aabb& box, const HeightField& ground,
                           UndersideRenderer& renderer, int reach_cells) {
  const Footprint fp = footprint_of(box, ground.grid());
  if (fp.empty()) return {};
  // bounding boxes first: the object is above the ground under its footprint (and within reach)
  const Grid& g = ground.grid();
  const int i0 = std::max(0, fp.i0 - reach_cells), j0 = std::max(0, fp.j0 - reach_cells);
  const int i1 = std::min(g.nx, fp.i0 + fp.ni + reach_cells), j1 = std::min(g.ny, fp.j0 + fp.nj + reach_cells);
  const double top = ground.heights().block(j0, i0, j1 - j0, i1 - i0).maxCoeff();
  // as displacement's contact test (displacement.h): an object resting on
  // ground it left at its underside touches it to round-off, and is no contact
  if (box.min.z() >= top - kContactToleranceFraction * g.cell_size_m) return {};
  const DepthImage img = renderer.render_below(faces_down, fp.sub_grid(ground.grid()), box.min.z(), box.max.z());
  Underside u;
  u.footprint = fp;
  u.top_m = box.max.z();
  u.z_m = ArrayXXdR::Constant(fp.nj, fp.ni, std::numeric_limits<double>::infinity());
  for (int j = 0; j < fp.nj; ++j) {
    for (int i = 0; i < fp.ni; ++i) {
      if (img.is_covered(i, j)) u.z_m(j, i) = img.z(i, j);
    }
  }
  return u;
}

}  // namespace

Underside find_underside_of_faces_down(const TriangleMesh& faces_down, const HeightField& ground,
                                       UndersideRenderer& renderer, int reach_cells) {
  return underside_in_box(faces_down, bounding_box(faces_down), ground, renderer, reach_cells);
}

Underside find_underside_of_faces_down(const FacesDown& faces_down, const HeightField& ground,
                                       UndersideRenderer& renderer, int reach_cells) {
  return underside_in_box(faces_down.mesh, faces_down.box, ground, renderer, reach_cells);
}

}  // namespace repose
