#pragma once
// A regular horizontal grid: nx by ny square cells of side cell_size_m. Cell
// (i, j) covers [origin_x + i*h, origin_x + (i+1)*h] x [origin_y + j*h, ...];
// its centre is at origin + (i + 0.5, j + 0.5) * h. x grows with i (columns),
// y with j (rows); z is up. Arrays over a grid are ny rows by nx columns.

#include <cstddef>
#include <optional>

namespace repose {

struct Grid {
  int nx = 0;
  int ny = 0;
  double cell_size_m = 0.0;
  double origin_x_m = 0.0;  // x of the grid's lower-left corner
  double origin_y_m = 0.0;  // y of the grid's lower-left corner

  std::size_t cell_count() const { return static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny); }
  double cell_area_m2() const { return cell_size_m * cell_size_m; }
  double extent_x_m() const { return nx * cell_size_m; }
  double extent_y_m() const { return ny * cell_size_m; }
  double centre_x(int i) const { return origin_x_m + (i + 0.5) * cell_size_m; }
  double centre_y(int j) const { return origin_y_m + (j + 0.5) * cell_size_m; }
  bool contains(int i, int j) const { return i >= 0 && j >= 0 && i < nx && j < ny; }
  bool operator==(const Grid&) const = default;

  // A grid over the same extent with cells `factor` times larger (factor >= 1);
  // nx and ny are rounded up, so the coarse grid may reach a little further.
  Grid coarsened(int factor) const;

  // The grid over exactly the same extent with cells of size h (> 0), or
  // nothing when h does not divide the extent (to 1e-6 of a cell).
  std::optional<Grid> with_cell_size(double h) const;
};

}  // namespace repose
