#include "models/tearing/tear_edge_layers.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/tearing/tear_path.h"

namespace repose {

void TearEdgeOptions::validate() const {
  const auto require = [](bool ok, const char* field, double value, const char* rule) {
    if (!ok) throw InputError(fmt::format("tearing edge: {} = {} must be {}", field, value, rule));
  };
  require(std::isfinite(layer_offset_m) && layer_offset_m >= 0.0, "layer_offset_m", layer_offset_m, ">= 0");
  require(std::abs(offset_direction.norm() - 1.0) < 1e-9, "offset_direction", offset_direction.norm(),
          "a unit vector");
  require(std::isfinite(search_half_width_m) && search_half_width_m >= 0.0, "search_half_width_m",
          search_half_width_m, ">= 0");
  require(std::isfinite(opening_m) && opening_m >= 0.0, "opening_m", opening_m, ">= 0");
}

namespace {

// The column in [lo, hi] where the layer is thinnest; ties go to the column
// nearest `centre`, then to the left one, so the choice does not depend on
// the scan direction more than it must.
int thinnest_column(const ArrayXXdR& layer, int row, int lo, int hi, int centre) {
  int best = std::clamp(centre, lo, hi);
  for (int c = lo; c <= hi; ++c) {
    const double d = layer(row, c), b = layer(row, best);
    if (d < b || (d == b && std::abs(c - centre) < std::abs(best - centre))) best = c;
  }
  return best;
}

// The tear path's x (m) at height y (m), linearly between its points; NaN
// outside its rows.
double path_x_at(const TearPath& path, double cell_m, double y) {
  for (std::size_t k = 0; k < path.points.size(); ++k) {
    if (std::abs(path.points[k].y() - y) <= 0.5 * cell_m) return path.points[k].x();
  }
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

LayerCuts trace_layer_cuts(const SheetModel& model, const SheetState& state, const FibreImages& images,
                           const TearEdgeOptions& options) {
  options.validate();
  const TearPath path = measure_tear_path(model, state);
  const double px = images.pixel_size_m;
  const int rows = images.ny(), cols = images.nx();
  const int band = std::max(1, static_cast<int>(std::lround(1.5 * model.cell_size_m / px)));
  const int search = static_cast<int>(std::lround(options.search_half_width_m / px));
  const double shift_px = options.layer_offset_m * options.offset_direction.x() / px;
  LayerCuts cuts;
  cuts.cut_x_m.assign(images.layers.size(), std::vector<double>(rows, std::numeric_limits<double>::quiet_NaN()));
  int previous = -1;
  for (int r = rows - 1; r >= 0; --r) {  // from the top edge down, as the tear ran
    const double along = path_x_at(path, model.cell_size_m, (r + 0.5) * px);
    if (std::isnan(along)) continue;
    const int centre = std::clamp(static_cast<int>(along / px), 0, cols - 1);
    const int lo = std::max(0, centre - band), hi = std::min(cols - 1, centre + band);
    // the top row looks across the whole band, later rows near the last cut
    const bool first = previous < 0;
    const int start = first ? centre : std::clamp(previous, lo, hi);
    const int cut = thinnest_column(images.layers[0], r, first ? lo : std::max(lo, start - search),
                                    first ? hi : std::min(hi, start + search), start);
    previous = cut;
    cuts.cut_x_m[0][r] = (cut + 0.5) * px;
    for (std::size_t k = 1; k < images.layers.size(); ++k) {
      const int from = std::clamp(static_cast<int>(std::lround(cuts.cut_x_m[k - 1][r] / px - 0.5 + shift_px)), 0, cols - 1);
      const int c = thinnest_column(images.layers[k], r, std::max(0, from - search), std::min(cols - 1, from + search), from);
      cuts.cut_x_m[k][r] = (c + 0.5) * px;
    }
  }
  return cuts;
}

RgbImage draw_layered_tear_edge(const FibreImages& images, const LayerCuts& cuts, const TearEdgeOptions& options) {
  options.validate();
  REPOSE_DEMAND(cuts.cut_x_m.size() == images.layers.size());
  RgbImage image;
  image.width = images.nx();
  image.height = images.ny();
  image.rgb.assign(static_cast<std::size_t>(image.width) * image.height * 3, 0);
  const double px = images.pixel_size_m, half_open = 0.5 * options.opening_m;
  for (int r = 0; r < image.height; ++r) {
    for (int c = 0; c < image.width; ++c) {
      const double x = (c + 0.5) * px;
      double colour[3] = {30.0, 30.0, 40.0};  // what lies behind the sheet
      for (int k = static_cast<int>(images.layers.size()) - 1; k >= 0; --k) {
        const double cut = cuts.cut_x_m[k][r];
        double source = x;  // intact rows: the layer lies where it is
        if (!std::isnan(cut)) {
          if (x + half_open < cut) {
            source = x + half_open;  // the left piece, pulled left
          } else if (x - half_open > cut) {
            source = x - half_open;  // the right piece, pulled right
          } else {
            continue;  // the gap this layer leaves
          }
        }
        const int sc = std::clamp(static_cast<int>(source / px), 0, image.width - 1);
        const double alpha = 0.35 + 0.6 * images.layers[k](r, sc);
        const double tint[3] = {k == 0 ? 90.0 : 245.0, k == 0 ? 200.0 : 245.0, k == 0 ? 90.0 : 240.0};
        for (int q = 0; q < 3; ++q) colour[q] = (1 - alpha) * colour[q] + alpha * tint[q];
      }
      std::uint8_t* out = &image.rgb[(static_cast<std::size_t>(image.height - 1 - r) * image.width + c) * 3];
      for (int q = 0; q < 3; ++q) out[q] = static_cast<std::uint8_t>(std::clamp(colour[q], 0.0, 255.0));
    }
  }
  return image;
}

}  // namespace repose
