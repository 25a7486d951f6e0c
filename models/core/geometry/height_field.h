#pragma once
// A height field: one height (m) per cell of a Grid. The height is the
// amount of material per unit area above z = 0, so volume = sum(h) * cell area.

#include <Eigen/Core>

#include "models/core/geometry/grid.h"

namespace repose {

// ny rows (y) by nx columns (x), row-major so that .data() is C order, as NumPy writes it.
using ArrayXXdR = Eigen::Array<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

class HeightField {
 public:
  HeightField() = default;
  explicit HeightField(const Grid& grid, double initial_height_m = 0.0);
  HeightField(const Grid& grid, ArrayXXdR heights);  // heights: ny x nx

  const Grid& grid() const { return grid_; }
  int nx() const { return grid_.nx; }
  int ny() const { return grid_.ny; }

  double& at(int i, int j) { return h_(j, i); }
  double at(int i, int j) const { return h_(j, i); }
  const ArrayXXdR& heights() const { return h_; }
  ArrayXXdR& heights() { return h_; }

  // Bilinear interpolation between cell centres; clamped to the edge cells outside.
  double sample(double x_m, double y_m) const;
  // Total material volume (m^3).
  double volume_m3() const;
  double min_height_m() const;  // of a non-empty field
  double max_height_m() const;
  bool all_finite() const { return h_.allFinite(); }

 private:
  Grid grid_;
  ArrayXXdR h_;
};

// Resample onto another grid by area-weighted averaging of overlapping cells
// (first-order conservative remap): the volume over the overlap of the two
// grids is conserved to round-off. Target cells outside the source keep 0.
HeightField resample_conservative(const HeightField& source, const Grid& target);

// Resample by bilinear interpolation at the target cell centres (smooth, not
// volume-conserving): for mapping a coarse result back onto a fine grid.
HeightField resample_bilinear(const HeightField& source, const Grid& target);

}  // namespace repose
