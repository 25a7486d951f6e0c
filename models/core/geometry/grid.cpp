#include "models/core/geometry/grid.h"

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

}  // namespace repose
