#pragma once
// Triangle meshes from and to files: Wavefront OBJ and STL (ASCII or binary).
// Units are whatever the file holds, taken as metres (scale in the scene).

#include <string>

#include "models/core/geometry/triangle_mesh.h"

namespace repose {

// Reads an .obj or .stl file (chosen by the extension, case-insensitive).
// OBJ: `v x y z [w]` and `f` lines (a, a/b, a//c, a/b/c forms; negative
// indices count back from the last vertex; polygons are fan-triangulated);
// other known OBJ statements are ignored, an unknown statement is an error.
// STL: binary when the file size is 84 + 50 * (triangle count in the
// header), else ASCII (`solid` ... `endsolid`); identical vertices are welded
// exactly, so a closed STL solid comes back as a closed manifold.
// Throws InputError naming the file, the line (text formats) and the reason:
// missing, a directory, unreadable, not a mesh, truncated, an index out of
// range, a non-finite coordinate. An empty result (no faces) is returned as
// such: the caller decides whether it needs a closed mesh.
TriangleMesh read_mesh(const std::string& path);

// Binary STL (float32 coordinates, facet normals from the vertices).
void write_stl(const std::string& path, const TriangleMesh& mesh);
// OBJ with coordinates printed round-trip exact.
void write_obj(const std::string& path, const TriangleMesh& mesh);
// Binary little-endian PLY: vertices as float64 x, y, z, faces as a uchar
// count and int32 indices (MeshLab, Blender, ParaView read it).
void write_ply(const std::string& path, const TriangleMesh& mesh);

}  // namespace repose
