#include "models/core/geometry/grid.h"

#include <cmath>

#include "models/core/base/error.h"

namespace repose {

Grid Grid::coarsened(int factor) const {
  REPOSE_DEMAND(factor >= 1);
  Grid g = *this;
  g.nx = (nx + factor - 1) / factor;
  g.ny = (ny + factor - 1) / factor;
  g.cell_size_m = cell_size_m * factor;
  return g;
}

std::optional<Grid> Grid::with_cell_size(double h) const {
  REPOSE_DEMAND(h > 0.0);
  const double cells_x = extent_x_m() / h, cells_y = extent_y_m() / h;
  Grid g = *this;
  g.nx = static_cast<int>(std::llround(cells_x));
  g.ny = static_cast<int>(std::llround(cells_y));
  g.cell_size_m = h;
  if (g.nx < 1 || g.ny < 1 || std::abs(cells_x - g.nx) > 1e-6 || std::abs(cells_y - g.ny) > 1e-6) return std::nullopt;
  return g;
}

}  // namespace repose
