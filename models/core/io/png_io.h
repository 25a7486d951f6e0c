#pragma once
// PNG images through libpng: 16-bit grey height maps and 8-bit RGB pictures.
// Files are read through InputFile (input_file.h): a regular file of at
// most input_kind::kPng bytes.
// PNG rows run top to bottom; a height map's first row is the grid's last
// (largest y), so the image looks like the ground seen from above with +y up.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "models/core/geometry/height_field.h"

namespace repose {

// 16-bit grey PNG -> ny x nx array of raw values 0..65535, row 0 = smallest y.
// 1-, 2-, 4- and 8-bit grey are accepted and scaled to 0..65535. Throws InputError.
ArrayXXdR read_png16(const std::string& path);
// As above, for a caller that knows the shape it needs (a height map for an
// ny x nx grid: rows = ny, cols = nx): a PNG whose header declares another
// size is refused from its header, before a pixel is decoded.
ArrayXXdR read_png16(const std::string& path, Eigen::Index rows, Eigen::Index cols);

// Width and height as a PNG's header declares them, read without decoding
// (for estimating memory before reading, memory_budget.h).
struct PngSize {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
};
PngSize read_png_size(const std::string& path);
// read_png16 with an optional expected size (width = nx, height = ny).
ArrayXXdR read_png16(const std::string& path, const std::optional<PngSize>& expected);
// Values are clamped to 0..65535 and rounded; row 0 (smallest y) is written last.
void write_png16(const std::string& path, const ArrayXXdR& values);

struct RgbImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  // width * height * 3, row 0 at the top
};
void write_png_rgb(const std::string& path, const RgbImage& image);
// Converts palette and grey images to RGB; drops alpha and 16-bit depth.
RgbImage read_png_rgb(const std::string& path);

}  // namespace repose
