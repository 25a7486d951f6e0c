#pragma once
// Height fields to and from files: NumPy .npy (for analysis), triangle meshes
// (OBJ, PLY: for Blender, MeshLab) and a VTK XML image (.vti: for ParaView).
//
// Meshes put one vertex at each cell centre (x, y of the centre, z = height):
// nx*ny vertices, vertex (i, j) is number j*nx + i (0-based); each quad of four
// neighbouring centres gives two triangles, counter-clockwise seen from above
// (normals point up): 2*(nx-1)*(ny-1) triangles.

#include <string>
#include <vector>

#include "models/core/geometry/height_field.h"

namespace repose {

// Reads a 2-D .npy array of ny rows x nx columns onto `grid`. Throws
// InputError naming the file and both shapes when they differ, or the first
// non-finite value.
HeightField read_height_field_npy(const std::string& path, const Grid& grid);
// Writes the heights as float64, ny rows x nx columns, row 0 = smallest y.
void write_height_field_npy(const std::string& path, const HeightField& field);

void write_height_field_obj(const std::string& path, const HeightField& field);

enum class PlyEncoding { kBinaryLittleEndian, kAscii };
// Vertices as float64 x, y, z; faces as a uchar count and int indices.
void write_height_field_ply(const std::string& path, const HeightField& field,
                            PlyEncoding encoding = PlyEncoding::kBinaryLittleEndian);

// An extra per-cell array for the .vti file, ny x nx like the heights (for
// example a material id). The name must be letters, digits, '_', '-' or '.'.
struct NamedCellArray {
  std::string name;
  ArrayXXdR values;
};
// A VTK XML ImageData file (ASCII) that ParaView opens: one point per cell
// centre, Origin = the first cell centre, Spacing = the cell size, point data
// "height_m" followed by the extra arrays. Throws InputError when an extra
// array has the wrong shape or an unusable name.
void write_height_field_vti(const std::string& path, const HeightField& field,
                            const std::vector<NamedCellArray>& extra_arrays = {});

}  // namespace repose
