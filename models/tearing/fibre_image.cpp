#include "models/tearing/fibre_image.h"

#include <algorithm>
#include <cmath>

#include "models/core/base/error.h"
#include "models/core/io/png_io.h"
#include "models/tearing/seeded_draw.h"

namespace repose {

namespace {

struct Clump {
  double x_m, y_m, angle_rad, width_m, length_m;
};

// Draw order is fixed: position, angle, width, length, per clump.
Clump draw_clump(const FibreOptions& o, double x0, double x1, double y0, double y1, std::mt19937_64& rng) {
  Clump c{};
  c.x_m = draw_between(rng, x0, x1);
  c.y_m = draw_between(rng, y0, y1);
  c.angle_rad = o.grain_direction_rad + draw_between(rng, -o.grain_spread_rad, o.grain_spread_rad);
  c.width_m = draw_between(rng, o.clump_width_min_m, o.clump_width_max_m);
  c.length_m = draw_between(rng, o.clump_length_min_m, o.clump_length_max_m);
  return c;
}

// Adds the clump's elliptical Gaussian (peak 1) to the pixels within three
// standard deviations of its axis.
void splat(const Clump& c, double pixel_m, ArrayXXdR* sum) {
  const double cs = std::cos(c.angle_rad), sn = std::sin(c.angle_rad);
  const double ex = 3.0 * std::hypot(c.length_m * cs, c.width_m * sn);
  const double ey = 3.0 * std::hypot(c.length_m * sn, c.width_m * cs);
  const int nx = static_cast<int>(sum->cols()), ny = static_cast<int>(sum->rows());
  const int i0 = std::max(0, static_cast<int>(std::floor((c.x_m - ex) / pixel_m)));
  const int i1 = std::min(nx - 1, static_cast<int>(std::floor((c.x_m + ex) / pixel_m)));
  const int j0 = std::max(0, static_cast<int>(std::floor((c.y_m - ey) / pixel_m)));
  const int j1 = std::min(ny - 1, static_cast<int>(std::floor((c.y_m + ey) / pixel_m)));
  const double inv_l2 = 1.0 / (c.length_m * c.length_m), inv_w2 = 1.0 / (c.width_m * c.width_m);
  for (int j = j0; j <= j1; ++j) {
    const double dy = (j + 0.5) * pixel_m - c.y_m;
    for (int i = i0; i <= i1; ++i) {
      const double dx = (i + 0.5) * pixel_m - c.x_m;
      const double along = dx * cs + dy * sn, across = -dx * sn + dy * cs;
      const double q = along * along * inv_l2 + across * across * inv_w2;
      if (q < 9.0) (*sum)(j, i) += std::exp(-0.5 * q);
    }
  }
}

int pixels_over(double extent_m, double pixel_m) {
  const double n = std::ceil(extent_m / pixel_m - 1e-9);
  if (!(n >= 1.0 && n <= 20000.0)) {
    throw InputError("tearing fibres: the image would have " + std::to_string(n) +
                     " pixels a side (allowed 1 to 20000): raise pixel_size_m or shrink the sheet");
  }
  return static_cast<int>(n);
}

}  // namespace

FibreImages draw_fibre_images(const FibreOptions& options, double width_m, double height_m, std::mt19937_64& rng) {
  options.validate();
  FibreImages images;
  images.pixel_size_m = options.pixel_size_m;
  const int nx = pixels_over(width_m, options.pixel_size_m), ny = pixels_over(height_m, options.pixel_size_m);
  const double margin = 3.0 * options.clump_length_max_m;
  const double x0 = -margin, x1 = width_m + margin, y0 = -margin, y1 = height_m + margin;
  const auto clumps = static_cast<long>(std::llround(options.clumps_per_m2 * (x1 - x0) * (y1 - y0)));
  images.composite = ArrayXXdR::Zero(ny, nx);
  for (int layer = 0; layer < options.layers; ++layer) {
    ArrayXXdR sum = ArrayXXdR::Zero(ny, nx);
    for (long k = 0; k < clumps; ++k) splat(draw_clump(options, x0, x1, y0, y1, rng), options.pixel_size_m, &sum);
    ArrayXXdR density = 1.0 - (1.0 - options.background_density) * (-sum).exp();
    images.composite += density;
    images.layers.push_back(std::move(density));
  }
  images.composite /= static_cast<double>(options.layers);
  return images;
}

FibreImages uniform_fibre_images(double width_m, double height_m, double pixel_size_m, double density) {
  if (!(pixel_size_m > 0.0)) throw InputError("tearing fibres: pixel_size_m must be > 0");
  if (!(density > 0.0 && density <= 1.0)) throw InputError("tearing fibres: a uniform density must be in (0, 1]");
  FibreImages images;
  images.pixel_size_m = pixel_size_m;
  images.composite = ArrayXXdR::Constant(pixels_over(height_m, pixel_size_m), pixels_over(width_m, pixel_size_m),
                                         density);
  images.layers.push_back(images.composite);
  return images;
}

std::vector<std::string> write_fibre_pngs(const FibreImages& images, const std::string& prefix) {
  std::vector<std::string> paths;
  for (std::size_t k = 0; k < images.layers.size(); ++k) {
    paths.push_back(prefix + "layer_" + std::to_string(k + 1) + ".png");
    write_png16(paths.back(), images.layers[k] * 65535.0);
  }
  paths.push_back(prefix + "composite.png");
  write_png16(paths.back(), images.composite * 65535.0);
  return paths;
}

}  // namespace repose
