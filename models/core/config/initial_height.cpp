#include "models/core/config/initial_height.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <random>
#include <vector>

#include "models/core/base/error.h"
#include "models/core/io/npy_io.h"
#include "models/core/io/png_io.h"

namespace repose {

namespace {

// A uniform double in [-1, 1) from 53 random bits: the same on every standard
// library (std::uniform_real_distribution is not).
double uniform_pm1(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-52 - 1.0; }

// Moving average of width 2r+1 along a line of n values with the given
// stride, the ends clamped (edge values repeated). O(n) whatever r is.
void box_filter_line(double* data, int n, std::ptrdiff_t stride, int r, std::vector<double>& scratch) {
  scratch.resize(static_cast<std::size_t>(n));
  auto at = [&](int k) { return data[static_cast<std::ptrdiff_t>(std::clamp(k, 0, n - 1)) * stride]; };
  double sum = 0.0;
  for (int k = -r; k <= r; ++k) sum += at(k);
  for (int k = 0; k < n; ++k) {
    scratch[static_cast<std::size_t>(k)] = sum / (2 * r + 1);
    sum += at(k + r + 1) - at(k - r);
  }
  for (int k = 0; k < n; ++k) data[static_cast<std::ptrdiff_t>(k) * stride] = scratch[static_cast<std::size_t>(k)];
}

// Three box passes of half-width r per axis have the variance of a Gaussian
// of standard deviation sigma when 3 * ((2r+1)^2 - 1) / 12 = sigma^2.
void smooth(ArrayXXdR& a, double sigma_cells) {
  const int ny = static_cast<int>(a.rows()), nx = static_cast<int>(a.cols());
  // wider than the grid changes nothing more (the edges are clamped): cap it
  const double r_real = (std::sqrt(4.0 * sigma_cells * sigma_cells + 1.0) - 1.0) / 2.0;
  const int r = static_cast<int>(std::lround(std::min(r_real, 2.0 * std::max(nx, ny))));
  if (r < 1) return;
  std::vector<double> scratch;
  for (int pass = 0; pass < 3; ++pass) {
    for (int j = 0; j < ny; ++j) box_filter_line(&a(j, 0), nx, 1, r, scratch);
    for (int i = 0; i < nx; ++i) box_filter_line(&a(0, i), ny, nx, r, scratch);
  }
}

HeightField noise_field(const Scene& scene) {
  const Grid& g = scene.ground.grid;
  const InitialHeight& init = scene.ground.initial;
  std::mt19937_64 rng(scene.seed);
  ArrayXXdR a(g.ny, g.nx);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) a(j, i) = uniform_pm1(rng);
  smooth(a, init.correlation_m / g.cell_size_m);
  a -= a.mean();
  const double peak = a.abs().maxCoeff();
  if (peak > 0.0) a *= init.amplitude_m / peak;
  a += init.height_m;
  return HeightField(g, std::move(a));
}

HeightField file_field(const Scene& scene) {
  const Grid& g = scene.ground.grid;
  const InitialHeight& init = scene.ground.initial;
  const bool png = std::filesystem::path(init.path).extension() == ".png";
  // the grid's shape is checked from the file's header, before decoding
  ArrayXXdR a = png ? ArrayXXdR(read_png16(init.path, g.ny, g.nx) * (init.png_height_scale_m / 65535.0))
                    : read_npy_2d(init.path, g.ny, g.nx);
  if (a.rows() != g.ny || a.cols() != g.nx) {
    throw InputError(init.path + ": the height array's shape no longer matches the scene's grid");
  }
  a += init.height_m;
  return HeightField(g, std::move(a));
}

}  // namespace

HeightField make_initial_height(const Scene& scene) {
  switch (scene.ground.initial.kind) {
    case InitialHeight::Kind::kFlat: return HeightField(scene.ground.grid, scene.ground.initial.height_m);
    case InitialHeight::Kind::kNoise: return noise_field(scene);
    case InitialHeight::Kind::kFile: return file_field(scene);
    case InitialHeight::Kind::kGiven:
      REPOSE_DEMAND(scene.ground.initial.given != nullptr && scene.ground.initial.given->grid() == scene.ground.grid);
      return *scene.ground.initial.given;
  }
  REPOSE_DEMAND(false);
  return {};
}

const std::string& material_at(const GroundSpec& ground, double x_m, double y_m) {
  for (auto r = ground.regions.rbegin(); r != ground.regions.rend(); ++r) {
    if (x_m >= r->x_min_m && x_m <= r->x_max_m && y_m >= r->y_min_m && y_m <= r->y_max_m) return r->material;
  }
  return ground.material;
}

}  // namespace repose
