#pragma once
// Collision of an object with the ground (the ground paper, 3.3): the
// object's bounding box is tested against the ground's heights under it,
// then a depth image from below is taken over the object's footprint only
// (one pixel per cell), so the cost follows the contact, not the grid. A
// cell collides where the object's underside lies below the ground height.

#include <algorithm>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "models/core/geometry/depth_image.h"
#include "models/core/geometry/grid.h"
#include "models/core/geometry/height_field.h"
#include "models/core/geometry/triangle_mesh.h"
#include "models/ground/faces_down.h"

namespace repose {

// A cell collides when its height exceeds the object's underside by more
// than this fraction of the cell size (displacement.h says why).
inline constexpr double kContactToleranceFraction = 1e-9;

// A rectangle of cells [i0, i0 + ni) x [j0, j0 + nj) of a grid.
struct Footprint {
  int i0 = 0, j0 = 0, ni = 0, nj = 0;
  bool empty() const { return ni <= 0 || nj <= 0; }
  bool contains(int i, int j) const { return i >= i0 && j >= j0 && i < i0 + ni && j < j0 + nj; }
  // The sub-grid of these cells (same cell size, shifted origin).
  Grid sub_grid(const Grid& grid) const;
};

// The smallest rectangle holding both (the other when one is empty).
inline Footprint bounding_box(const Footprint& a, const Footprint& b) {
  if (a.empty()) return b;
  if (b.empty()) return a;
  const int i0 = std::min(a.i0, b.i0), j0 = std::min(a.j0, b.j0);
  return Footprint{i0, j0, std::max(a.i0 + a.ni, b.i0 + b.ni) - i0, std::max(a.j0 + a.nj, b.j0 + b.nj) - j0};
}

// The cells of `grid` whose centres lie inside the box's xy extent.
Footprint footprint_of(const Aabb& box, const Grid& grid);

// Renders an object's underside over a sub-grid. Implementations: CPU ray
// casting (depth_image_cpu) and OpenGL through OSMesa.
class UndersideRenderer {
 public:
  virtual ~UndersideRenderer() = default;
  virtual std::string name() const = 0;  // "cpu" or "osmesa"
  // Depth image from below over `sub`; the mesh lies within [z_min_m, z_max_m].
  virtual DepthImage render_below(const TriangleMesh& mesh, const Grid& sub, double z_min_m, double z_max_m) = 0;
};

std::unique_ptr<UndersideRenderer> make_cpu_underside_renderer();
// Throws InputError when OpenGL through OSMesa cannot be started.
std::unique_ptr<UndersideRenderer> make_osmesa_underside_renderer();

// An object's underside over its footprint.
struct Underside {
  Footprint footprint;
  ArrayXXdR z_m;  // footprint.nj x footprint.ni; +inf where the object is not over the cell
  // The object's highest point: displaced material heaps no higher beside it
  // (excess_routing.h). -inf when unknown (an underside made by hand).
  double top_m = -std::numeric_limits<double>::infinity();
  bool empty() const { return footprint.empty(); }
  // +inf outside the footprint.
  double at(int i, int j) const {
    return footprint.contains(i, j) ? z_m(j - footprint.j0, i - footprint.i0) : std::numeric_limits<double>::infinity();
  }
};

// The underside of `mesh` (world coordinates) over the ground; empty when
// the bounding box misses the grid or lies wholly above the ground under it
// and within `reach_cells` cells around (0: a contact; more: an object that
// ground could rise under, e.g. by erosion, which moves material one cell per pass).
Underside find_underside(const TriangleMesh& mesh, const HeightField& ground, UndersideRenderer& renderer,
                         int reach_cells = 0);
// The same for a mesh of which only the faces turned down are left
// (faces_turned(mesh, true), which keeps every vertex, so the bounding box
// is the whole mesh's): a step makes that once per object and looks from
// below with it up to three times (fine, coarse, hovering).
Underside find_underside_of_faces_down(const TriangleMesh& faces_down, const HeightField& ground,
                                       UndersideRenderer& renderer, int reach_cells = 0);
// The same with the box given (faces_down.h): the mesh may then keep only
// the vertices its faces use, and its box is not computed again.
Underside find_underside_of_faces_down(const FacesDown& faces_down, const HeightField& ground,
                                       UndersideRenderer& renderer, int reach_cells = 0);

// The undersides of all objects in a step. The lowest one over a cell is
// how high the ground there may rise (displacement and erosion never push
// material above an object).
struct Ceiling {
  std::vector<Underside> undersides;
  double at(int i, int j) const {
    double z = std::numeric_limits<double>::infinity();
    for (const Underside& u : undersides) z = std::min(z, u.at(i, j));
    return z;
  }
};

}  // namespace repose
