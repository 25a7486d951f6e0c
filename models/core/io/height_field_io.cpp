#include "models/core/io/height_field_io.h"

#include <fmt/format.h>

#include <bit>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <utility>

#include "models/core/base/error.h"
#include "models/core/io/npy_io.h"

namespace repose {
namespace {

// Writes `text` to `path`, so that each writer builds its file in memory and
// every write error is reported in one place.
void write_file(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw InputError(fmt::format("{}: cannot open for writing: {}", path, std::strerror(errno)));
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  out.close();
  if (!out) throw InputError(fmt::format("{}: write failed: {}", path, std::strerror(errno)));
}

struct Triangle {
  int a, b, c;
};

// Two counter-clockwise (seen from above) triangles per quad of cell centres.
std::vector<Triangle> centre_triangles(int nx, int ny) {
  std::vector<Triangle> tris;
  if (nx < 2 || ny < 2) return tris;
  tris.reserve(static_cast<std::size_t>(2) * (nx - 1) * (ny - 1));
  for (int j = 0; j + 1 < ny; ++j) {
    for (int i = 0; i + 1 < nx; ++i) {
      const int v00 = j * nx + i;
      const int v10 = v00 + 1;
      const int v01 = v00 + nx;
      const int v11 = v01 + 1;
      tris.push_back({v00, v10, v11});
      tris.push_back({v00, v11, v01});
    }
  }
  return tris;
}

void append_le(std::string& out, std::uint64_t v, int bytes) {
  for (int k = 0; k < bytes; ++k) out.push_back(static_cast<char>((v >> (8 * k)) & 0xff));
}

bool is_safe_array_name(const std::string& name) {
  if (name.empty()) return false;
  for (char ch : name) {
    const bool ok = (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') || ch == '_' ||
                    ch == '-' || ch == '.';
    if (!ok) return false;
  }
  return true;
}

void append_vti_array(std::string& out, const std::string& name, const ArrayXXdR& values) {
  out += fmt::format("        <DataArray type=\"Float64\" Name=\"{}\" NumberOfComponents=\"1\" format=\"ascii\">\n",
                     name);
  // point order is x fastest, then y: the row-major order of a ny x nx array
  for (Eigen::Index j = 0; j < values.rows(); ++j) {
    out += "          ";
    for (Eigen::Index i = 0; i < values.cols(); ++i) {
      if (i > 0) out += ' ';
      out += fmt::format("{}", values(j, i));
    }
    out += '\n';
  }
  out += "        </DataArray>\n";
}

}  // namespace

HeightField read_height_field_npy(const std::string& path, const Grid& grid) {
  ArrayXXdR h = read_npy_2d(path);
  if (h.rows() != grid.ny || h.cols() != grid.nx) {
    throw InputError(fmt::format("{}: array shape ({}, {}) does not match the grid: expected ({}, {}) (ny rows, nx "
                                 "columns)",
                                 path, h.rows(), h.cols(), grid.ny, grid.nx));
  }
  for (Eigen::Index j = 0; j < h.rows(); ++j) {
    for (Eigen::Index i = 0; i < h.cols(); ++i) {
      if (!std::isfinite(h(j, i))) {
        throw InputError(fmt::format("{}: height at row {}, column {} is {}; heights must be finite", path, j, i,
                                     h(j, i)));
      }
    }
  }
  return HeightField(grid, std::move(h));
}

void write_height_field_npy(const std::string& path, const HeightField& field) {
  write_npy_2d(path, field.heights(), NpyType::kFloat64);
}

void write_height_field_obj(const std::string& path, const HeightField& field) {
  const Grid& g = field.grid();
  std::string out = fmt::format("# repose height field: {} x {} cells of {} m; one vertex per cell centre\n", g.nx,
                                g.ny, g.cell_size_m);
  for (int j = 0; j < g.ny; ++j) {
    for (int i = 0; i < g.nx; ++i) out += fmt::format("v {} {} {}\n", g.centre_x(i), g.centre_y(j), field.at(i, j));
  }
  // OBJ indices are 1-based
  for (const Triangle& t : centre_triangles(g.nx, g.ny)) out += fmt::format("f {} {} {}\n", t.a + 1, t.b + 1, t.c + 1);
  write_file(path, out);
}

void write_height_field_ply(const std::string& path, const HeightField& field, PlyEncoding encoding) {
  const Grid& g = field.grid();
  const std::vector<Triangle> tris = centre_triangles(g.nx, g.ny);
  const bool binary = encoding == PlyEncoding::kBinaryLittleEndian;
  std::string out = fmt::format(
      "ply\nformat {} 1.0\ncomment repose height field: one vertex per cell centre\n"
      "element vertex {}\nproperty double x\nproperty double y\nproperty double z\n"
      "element face {}\nproperty list uchar int vertex_indices\nend_header\n",
      binary ? "binary_little_endian" : "ascii", g.cell_count(), tris.size());
  for (int j = 0; j < g.ny; ++j) {
    for (int i = 0; i < g.nx; ++i) {
      const double xyz[3] = {g.centre_x(i), g.centre_y(j), field.at(i, j)};
      if (binary) {
        for (double v : xyz) append_le(out, std::bit_cast<std::uint64_t>(v), 8);
      } else {
        out += fmt::format("{} {} {}\n", xyz[0], xyz[1], xyz[2]);
      }
    }
  }
  for (const Triangle& t : tris) {
    if (binary) {
      out.push_back('\x03');
      for (int v : {t.a, t.b, t.c}) append_le(out, static_cast<std::uint32_t>(v), 4);
    } else {
      out += fmt::format("3 {} {} {}\n", t.a, t.b, t.c);
    }
  }
  write_file(path, out);
}

void write_height_field_vti(const std::string& path, const HeightField& field,
                            const std::vector<NamedCellArray>& extra_arrays) {
  const Grid& g = field.grid();
  for (const NamedCellArray& a : extra_arrays) {
    if (!is_safe_array_name(a.name) || a.name == "height_m") {
      throw InputError(fmt::format("{}: VTK array name '{}' must be new and use only letters, digits, '_', '-', '.'",
                                   path, a.name));
    }
    if (a.values.rows() != g.ny || a.values.cols() != g.nx) {
      throw InputError(fmt::format("{}: VTK array '{}' has shape ({}, {}); expected ({}, {}) like the heights", path,
                                   a.name, a.values.rows(), a.values.cols(), g.ny, g.nx));
    }
  }
  const std::string extent = fmt::format("0 {} 0 {} 0 0", g.nx - 1, g.ny - 1);
  std::string out = "<?xml version=\"1.0\"?>\n";
  out += "<VTKFile type=\"ImageData\" version=\"0.1\" byte_order=\"LittleEndian\">\n";
  out += fmt::format("  <ImageData WholeExtent=\"{}\" Origin=\"{} {} 0\" Spacing=\"{} {} {}\">\n", extent,
                     g.centre_x(0), g.centre_y(0), g.cell_size_m, g.cell_size_m, g.cell_size_m);
  out += fmt::format("    <Piece Extent=\"{}\">\n", extent);
  out += "      <PointData Scalars=\"height_m\">\n";
  append_vti_array(out, "height_m", field.heights());
  for (const NamedCellArray& a : extra_arrays) append_vti_array(out, a.name, a.values);
  out += "      </PointData>\n      <CellData>\n      </CellData>\n    </Piece>\n  </ImageData>\n</VTKFile>\n";
  write_file(path, out);
}

}  // namespace repose
