#include "models/core/io/mesh_io.h"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "models/core/base/error.h"
#include "tests/support/temp_dir.h"

namespace repose {
namespace {

namespace fs = std::filesystem;

const fs::path kMeshes = fs::path(REPOSE_SOURCE_DIR) / "tests/data/meshes";

// A scratch folder per test (dir_.path), removed afterwards.
class MeshIo : public test_support::TempDirTest {
 protected:
  std::string file(const std::string& name, const std::string& text) const {
    const std::string p = path(name);
    std::ofstream(p, std::ios::binary) << text;
    return p;
  }
};

std::string error_of(const std::string& path) {
  try {
    read_mesh(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST_F(MeshIo, ReadsTheClosedCube) {
  const TriangleMesh m = read_mesh((kMeshes / "cube.obj").string());
  EXPECT_EQ(m.V.rows(), 8);
  EXPECT_EQ(m.F.rows(), 12);  // six quads, fan-triangulated
  EXPECT_TRUE(is_closed_manifold(m));
  EXPECT_NEAR(signed_volume_m3(m), 1.0, 1e-15);
}

TEST_F(MeshIo, ReadsTheBucket) {
  const TriangleMesh m = read_mesh((kMeshes / "bucket.obj").string());
  EXPECT_TRUE(is_closed_manifold(m));
  EXPECT_NEAR(signed_volume_m3(m), 1.0 * 1.0 * 0.6 - 0.8 * 0.8 * 0.5, 1e-12);
  const Aabb box = bounding_box(m);
  EXPECT_NEAR((box.max - Eigen::Vector3d(0.5, 0.5, 0.6)).norm(), 0.0, 1e-15);
}

TEST_F(MeshIo, WeldsAsciiStlVertices) {
  const TriangleMesh m = read_mesh((kMeshes / "cube_ascii.stl").string());
  EXPECT_EQ(m.V.rows(), 8);
  EXPECT_EQ(m.F.rows(), 12);
  EXPECT_TRUE(is_closed_manifold(m));
  EXPECT_NEAR(signed_volume_m3(m), 1.0, 1e-15);
}

TEST_F(MeshIo, OpenAndEmptyMeshesAreReadButNotClosed) {
  const TriangleMesh open = read_mesh((kMeshes / "open_box.obj").string());
  EXPECT_EQ(open.F.rows(), 10);
  EXPECT_FALSE(is_closed_manifold(open));
  EXPECT_TRUE(read_mesh((kMeshes / "empty.obj").string()).empty());
}

TEST_F(MeshIo, RefusesWhatIsNotAMesh) {
  const std::string text = error_of((kMeshes / "not_a_mesh.obj").string());
  EXPECT_NE(text.find("not_a_mesh.obj:1: unknown OBJ statement 'This'"), std::string::npos) << text;
  EXPECT_NE(error_of((kMeshes / "not_a_mesh.stl").string()).find("not an STL file"), std::string::npos);
  EXPECT_NE(error_of(kMeshes.string()).find("expected a .obj or .stl"), std::string::npos);
  EXPECT_NE(error_of(path("missing.obj")).find("no such file"), std::string::npos);
  fs::create_directories(dir_.path / "folder.stl");
  EXPECT_NE(error_of(path("folder.stl")).find("is a directory"), std::string::npos);
  EXPECT_NE(error_of(file("mesh.ply", "ply\n")).find("expected a .obj or .stl"), std::string::npos);
}

TEST_F(MeshIo, ObjFaceFormsAndNegativeIndices) {
  const std::string p = file("forms.obj",
                             "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n"
                             "f 1/1/1 2/1/1 3/1/1\n"
                             "f 1//1 3//1 4//1\n"
                             "f -4 -3 -2 -1\n");
  const TriangleMesh m = read_mesh(p);
  ASSERT_EQ(m.F.rows(), 4);
  EXPECT_EQ(m.F.row(0), Eigen::RowVector3i(0, 1, 2));
  EXPECT_EQ(m.F.row(1), Eigen::RowVector3i(0, 2, 3));
  EXPECT_EQ(m.F.row(2), Eigen::RowVector3i(0, 1, 2));  // fan of the quad 1 2 3 4
  EXPECT_EQ(m.F.row(3), Eigen::RowVector3i(0, 2, 3));
}

TEST_F(MeshIo, ObjErrorsNameTheLine) {
  EXPECT_NE(error_of(file("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n")).find("range.obj:4: face index 4 out of range"),
            std::string::npos);
  EXPECT_NE(error_of(file("zero.obj", "v 0 0 0\nf 0 1 1\n")).find("zero.obj:2: face index 0"), std::string::npos);
  EXPECT_NE(error_of(file("nan.obj", "v 0 0 0\nv nan 0 0\n")).find("nan.obj:2: non-finite coordinate"), std::string::npos);
  EXPECT_NE(error_of(file("word.obj", "v 0 zero 0\n")).find("word.obj:1: 'zero' is not a number"), std::string::npos);
}

TEST_F(MeshIo, StlRoundTripKeepsAClosedManifoldAndItsVolume) {
  const TriangleMesh sphere = make_sphere(0.3, 24);
  const std::string p = path("sphere.stl");
  write_stl(p, sphere);
  EXPECT_EQ(fs::file_size(p), 84u + 50u * static_cast<std::uintmax_t>(sphere.F.rows()));
  const TriangleMesh back = read_mesh(p);
  EXPECT_EQ(back.V.rows(), sphere.V.rows());
  EXPECT_EQ(back.F.rows(), sphere.F.rows());
  EXPECT_TRUE(is_closed_manifold(back));
  // float32 coordinates: relative error ~1e-7
  EXPECT_NEAR(signed_volume_m3(back), signed_volume_m3(sphere), 1e-6 * signed_volume_m3(sphere));
}

// LIGGGHTS reads the first line of an STL file as text (looking for
// "solid"); it must end inside the 80-byte header, before triangle data whose
// bytes may hold quotes that LIGGGHTS's parser rejects.
TEST_F(MeshIo, BinaryStlFirstLineEndsInsideTheHeaderAndIsNotSolid) {
  const std::string p = path("line.stl");
  write_stl(p, transformed(make_sphere(0.03, 24), Pose{Eigen::Vector3d(0.045, 0.055, 0.054), Eigen::Quaterniond::Identity()}));
  std::ifstream in(p, std::ios::binary);
  std::string first_line;
  std::getline(in, first_line);
  EXPECT_LT(first_line.size(), 80u);
  EXPECT_EQ(first_line.find('\0'), std::string::npos);
  EXPECT_FALSE(first_line.starts_with("solid"));
}

TEST_F(MeshIo, BinaryStlWhoseHeaderSaysSolidIsStillBinary) {
  const std::string p = path("solid.stl");
  write_stl(p, make_box({1, 2, 3}));
  {
    std::fstream f(p, std::ios::in | std::ios::out | std::ios::binary);
    f.write("solid box", 9);
  }
  const TriangleMesh m = read_mesh(p);
  EXPECT_TRUE(is_closed_manifold(m));
  EXPECT_NEAR(signed_volume_m3(m), 48.0, 1e-9);
}

TEST_F(MeshIo, TruncatedBinaryStlIsRefused) {
  const std::string p = path("cut.stl");
  write_stl(p, make_box({1, 1, 1}));
  fs::resize_file(p, fs::file_size(p) - 10);
  EXPECT_NE(error_of(p).find("truncated"), std::string::npos) << error_of(p);
}

TEST_F(MeshIo, ObjRoundTripIsExact) {
  const TriangleMesh capsule = make_capsule(0.1, 0.25, 16);
  const std::string p = path("capsule.obj");
  write_obj(p, capsule);
  const TriangleMesh back = read_mesh(p);
  EXPECT_EQ(back.V, capsule.V);
  EXPECT_EQ(back.F, capsule.F);
}

TEST_F(MeshIo, PlyHoldsTheHeaderCountsAndEveryVertexBitExact) {
  const TriangleMesh cube = make_box(Eigen::Vector3d(0.5, 0.25, 1.0 / 3.0));
  write_ply(path("cube.ply"), cube);
  std::ifstream in(path("cube.ply"), std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string end = "end_header\n";
  const std::size_t body = bytes.find(end) + end.size();
  ASSERT_NE(bytes.find(end), std::string::npos);
  EXPECT_NE(bytes.find("element vertex " + std::to_string(cube.V.rows()) + "\n"), std::string::npos);
  EXPECT_NE(bytes.find("element face " + std::to_string(cube.F.rows()) + "\n"), std::string::npos);
  ASSERT_EQ(bytes.size(), body + 24 * cube.V.rows() + 13 * cube.F.rows());
  for (Eigen::Index v = 0; v < cube.V.rows(); ++v) {
    for (int d = 0; d < 3; ++d) {
      double x;
      std::memcpy(&x, bytes.data() + body + 24 * v + 8 * d, 8);
      EXPECT_EQ(x, cube.V(v, d));
    }
  }
  const std::size_t faces = body + 24 * cube.V.rows();
  for (Eigen::Index f = 0; f < cube.F.rows(); ++f) {
    EXPECT_EQ(bytes[faces + 13 * f], 3);
    std::int32_t i;
    std::memcpy(&i, bytes.data() + faces + 13 * f + 1 + 4 * 2, 4);
    EXPECT_EQ(i, cube.F(f, 2));
  }
}

}  // namespace
}  // namespace repose
