#include "models/snow/ground_surface_mesh.h"

namespace repose {

TriangleMesh ground_surface_mesh(const HeightField& ground) {
  const Grid& g = ground.grid();
  TriangleMesh mesh;
  mesh.V.resize(static_cast<Eigen::Index>(g.cell_count()), 3);
  for (int j = 0; j < g.ny; ++j) {
    for (int i = 0; i < g.nx; ++i) {
      mesh.V.row(static_cast<Eigen::Index>(j) * g.nx + i) << g.centre_x(i), g.centre_y(j), ground.at(i, j);
    }
  }
  const int squares = std::max(0, g.nx - 1) * std::max(0, g.ny - 1);
  mesh.F.resize(2 * squares, 3);
  Eigen::Index f = 0;
  for (int j = 0; j + 1 < g.ny; ++j) {
    for (int i = 0; i + 1 < g.nx; ++i) {
      const int a = j * g.nx + i, b = a + 1, c = a + g.nx, d = c + 1;
      mesh.F.row(f++) << a, b, d;  // counter-clockwise seen from above
      mesh.F.row(f++) << a, d, c;
    }
  }
  return mesh;
}

}  // namespace repose
