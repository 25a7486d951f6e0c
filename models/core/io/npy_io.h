#pragma once
// NumPy .npy arrays (format versions 1.0 to 3.0), little-endian float32 or
// float64, C or Fortran order. Reading checks the magic, the header, the
// dtype and that the file holds as many bytes as the shape says.

#include <cstdint>
#include <string>
#include <vector>

#include "models/core/geometry/height_field.h"

namespace repose {

enum class NpyType { kFloat32, kFloat64 };

// A 2-D array read from a .npy file, as doubles, ny rows x nx columns. A 1-D
// array of n reads as 1 x n; integer types <i2 <u2 <i4 |u1 convert exactly;
// bytes after the data are an error. The file is read through InputFile
// (input_file.h): a regular file of at most input_kind::kNpy bytes.
// Throws InputError naming the file and what is wrong.
ArrayXXdR read_npy_2d(const std::string& path);
// As above, for a caller that knows the shape it needs (a height map for an
// ny x nx grid): a file whose header declares another shape is refused from
// the header, before its data is read or memory allocated for it.
ArrayXXdR read_npy_2d(const std::string& path, Eigen::Index rows, Eigen::Index cols);

// The rows and columns a .npy file declares (1-D: 1 x n), read from its
// header alone after checking the header and that the file holds exactly the
// data it declares. For estimating memory before reading (memory_budget.h).
struct NpyShape {
  std::uint64_t rows = 0;
  std::uint64_t cols = 0;
};
NpyShape read_npy_shape(const std::string& path);
// Writes a 2-D array (rows x cols, C order).
void write_npy_2d(const std::string& path, const ArrayXXdR& a, NpyType type = NpyType::kFloat64);
// Writes a 1-D array.
void write_npy_1d(const std::string& path, const std::vector<double>& a, NpyType type = NpyType::kFloat64);

}  // namespace repose
