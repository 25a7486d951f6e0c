#include "models/tearing/tear_image.h"

#include <algorithm>
#include <cstdint>

#include "models/core/base/error.h"

namespace repose {

RgbImage draw_tear_image(const SheetModel& model, const SheetState& state, const FibreImages& images,
                         int pixels_per_cell) {
  if (pixels_per_cell < 1 || pixels_per_cell > 64) throw InputError("tear image: pixels_per_cell must be in [1, 64]");
  RgbImage image;
  image.width = model.cells_x * pixels_per_cell;
  image.height = model.cells_y * pixels_per_cell;
  image.rgb.resize(static_cast<std::size_t>(image.width) * image.height * 3);
  const double metres_per_pixel = model.cell_size_m / pixels_per_cell;
  for (int row = 0; row < image.height; ++row) {
    const int py = image.height - 1 - row;  // row 0 at the top of the picture
    for (int col = 0; col < image.width; ++col) {
      const int cell = model.cell(col / pixels_per_cell, py / pixels_per_cell);
      const int ix = std::min(images.nx() - 1, static_cast<int>((col + 0.5) * metres_per_pixel / images.pixel_size_m));
      const int iy = std::min(images.ny() - 1, static_cast<int>((py + 0.5) * metres_per_pixel / images.pixel_size_m));
      const auto grey = static_cast<std::uint8_t>(std::clamp(255.0 * (1.0 - 0.8 * images.composite(iy, ix)), 0.0, 255.0));
      std::uint8_t* out = &image.rgb[(static_cast<std::size_t>(row) * image.width + col) * 3];
      const int torn = state.torn_step[static_cast<std::size_t>(cell)];
      out[0] = torn > 0 ? 220 : (torn == 0 ? 40 : grey);
      out[1] = torn >= 0 ? 40 : grey;
      out[2] = torn > 0 ? 40 : (torn == 0 ? 220 : grey);
    }
  }
  return image;
}

}  // namespace repose
