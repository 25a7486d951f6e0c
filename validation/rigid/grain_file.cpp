#include "validation/rigid/grain_file.h"

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/core/io/npy_io.h"

namespace repose {

void write_grains_npy(const std::string& path, const GrainSet& grains) {
  ArrayXXdR a(grains.size(), 4);
  for (Eigen::Index g = 0; g < grains.size(); ++g) {
    a.row(g) << grains.position_m(g, 0), grains.position_m(g, 1), grains.position_m(g, 2), grains.radius_m(g);
  }
  write_npy_2d(path, a);
}

GrainSet read_grains_npy(const std::string& path) {
  const ArrayXXdR a = read_npy_2d(path);
  if (a.cols() != 4) throw InputError(fmt::format("{}: expected #G by 4 (x y z r), got {} columns", path, a.cols()));
  GrainSet grains;
  grains.position_m = a.leftCols(3).matrix();
  grains.radius_m = a.col(3).matrix();
  return grains;
}

}  // namespace repose
