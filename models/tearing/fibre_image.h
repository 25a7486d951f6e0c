#pragma once
// Fibre-density images (the seed paper's section 3.1): one image per layer
// and their composite, each a ny x nx array of densities in [0, 1] over the
// sheet (row 0 at the smallest y, as models/core/io/png_io.h writes height
// maps). How clumps are drawn: fibre_options.h.

#include <random>
#include <string>
#include <vector>

#include "models/core/geometry/height_field.h"
#include "models/tearing/fibre_options.h"

namespace repose {

struct FibreImages {
  double pixel_size_m = 0.0;
  std::vector<ArrayXXdR> layers;  // options.layers arrays, ny x nx, in [0, 1]
  ArrayXXdR composite;            // mean of the layers

  int nx() const { return static_cast<int>(composite.cols()); }
  int ny() const { return static_cast<int>(composite.rows()); }
};

// Images covering a width_m x height_m sheet (ceil(extent / pixel) pixels a
// side). Clumps are scattered over the sheet grown by three clump lengths on
// every side, so the edges are as dense as the middle. Every draw comes from
// rng, in a fixed order: same options and seed, same bits.
FibreImages draw_fibre_images(const FibreOptions& options, double width_m, double height_m, std::mt19937_64& rng);

// A single layer of uniform density (for tests and for a sheet without fibres).
FibreImages uniform_fibre_images(double width_m, double height_m, double pixel_size_m, double density);

// Writes <prefix>layer_<k>.png (k from 1, the top layer) and
// <prefix>composite.png as 16-bit grey PNGs, density 1 = 65535.
// Returns the paths written.
std::vector<std::string> write_fibre_pngs(const FibreImages& images, const std::string& prefix);

}  // namespace repose
