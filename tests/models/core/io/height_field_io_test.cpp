#include "models/core/io/height_field_io.h"

#include <gtest/gtest.h>
#include <Eigen/Geometry>
#include <unistd.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include "models/core/base/error.h"
#include "models/core/io/npy_io.h"

#include "tests/support/temp_dir.h"

namespace repose {
namespace {

namespace fs = std::filesystem;

class HeightFieldIo : public test_support::TempDirTest {};

using test_support::read_all;
using test_support::write_all;

// A wavy field with negative heights, on a grid not at the origin.
HeightField wavy_field(int nx, int ny) {
  const Grid g{nx, ny, 0.05, -0.7, 0.3};
  HeightField f(g);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) f.at(i, j) = 0.1 * std::sin(1.3 * i) * std::cos(0.7 * j) - 0.01 * j + 1e-3 / (i + 1);
  return f;
}

struct Mesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<long, 3>> faces;  // 0-based
};

// ---- tiny readers, independent of the writers ----

Mesh parse_obj(const std::string& path) {
  Mesh m;
  std::istringstream in(read_all(path));
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::string tag;
    ls >> tag;
    if (tag == "v") {
      Eigen::Vector3d v;
      ls >> v.x() >> v.y() >> v.z();
      EXPECT_FALSE(ls.fail()) << line;
      m.vertices.push_back(v);
    } else if (tag == "f") {
      std::array<long, 3> f{};
      ls >> f[0] >> f[1] >> f[2];
      EXPECT_FALSE(ls.fail()) << line;
      for (long& k : f) k -= 1;
      m.faces.push_back(f);
    } else {
      EXPECT_TRUE(tag.empty() || tag[0] == '#') << line;
    }
  }
  return m;
}

Mesh parse_ply(const std::string& path) {
  const std::string bytes = read_all(path);
  const std::size_t end = bytes.find("end_header\n");
  EXPECT_NE(end, std::string::npos);
  std::istringstream header(bytes.substr(0, end));
  std::string line, format;
  long n_vertices = -1, n_faces = -1;
  std::vector<std::string> properties;
  while (std::getline(header, line)) {
    std::istringstream ls(line);
    std::string word;
    ls >> word;
    if (word == "format") ls >> format;
    if (word == "element") {
      std::string name;
      long count;
      ls >> name >> count;
      (name == "vertex" ? n_vertices : n_faces) = count;
    }
    if (word == "property") properties.push_back(line);
  }
  EXPECT_EQ(properties, (std::vector<std::string>{"property double x", "property double y", "property double z",
                                                  "property list uchar int vertex_indices"}));
  Mesh m;
  std::size_t pos = end + std::strlen("end_header\n");
  if (format == "ascii") {
    std::istringstream body(bytes.substr(pos));
    for (long k = 0; k < n_vertices; ++k) {
      Eigen::Vector3d v;
      body >> v.x() >> v.y() >> v.z();
      m.vertices.push_back(v);
    }
    for (long k = 0; k < n_faces; ++k) {
      int count;
      std::array<long, 3> f{};
      body >> count >> f[0] >> f[1] >> f[2];
      EXPECT_EQ(count, 3);
      m.faces.push_back(f);
    }
    EXPECT_FALSE(body.fail());
    std::string rest;
    body >> rest;
    EXPECT_TRUE(rest.empty()) << "trailing data: " << rest;
    return m;
  }
  EXPECT_EQ(format, "binary_little_endian");
  EXPECT_EQ(bytes.size(), pos + n_vertices * 24 + n_faces * 13);
  auto le = [&](int nbytes) {
    std::uint64_t v = 0;
    for (int k = nbytes - 1; k >= 0; --k) v = (v << 8) | static_cast<unsigned char>(bytes.at(pos + k));
    pos += nbytes;
    return v;
  };
  for (long k = 0; k < n_vertices; ++k) {
    Eigen::Vector3d v;
    for (int c = 0; c < 3; ++c) v[c] = std::bit_cast<double>(le(8));
    m.vertices.push_back(v);
  }
  for (long k = 0; k < n_faces; ++k) {
    EXPECT_EQ(le(1), 3u);
    std::array<long, 3> f{};
    for (long& idx : f) idx = static_cast<std::int32_t>(static_cast<std::uint32_t>(le(4)));
    m.faces.push_back(f);
  }
  return m;
}

// Vertices at the cell centres with z = height; two upward triangles per quad
// that tile the rectangle spanned by the centres exactly once.
void expect_centre_mesh(const Mesh& m, const HeightField& f) {
  const Grid& g = f.grid();
  ASSERT_EQ(m.vertices.size(), g.cell_count());
  ASSERT_EQ(m.faces.size(), static_cast<std::size_t>(2 * std::max(g.nx - 1, 0) * std::max(g.ny - 1, 0)));
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const Eigen::Vector3d& v = m.vertices[static_cast<std::size_t>(j) * g.nx + i];
      EXPECT_EQ(v.x(), g.centre_x(i));
      EXPECT_EQ(v.y(), g.centre_y(j));
      EXPECT_EQ(v.z(), f.at(i, j));  // shortest round-trip text or raw doubles: exact
    }
  double area = 0.0;
  std::vector<int> uses(m.vertices.size(), 0);
  for (const auto& t : m.faces) {
    for (long k : t) {
      ASSERT_GE(k, 0);
      ASSERT_LT(k, static_cast<long>(m.vertices.size()));
      ++uses[k];
    }
    const Eigen::Vector3d n = (m.vertices[t[1]] - m.vertices[t[0]]).cross(m.vertices[t[2]] - m.vertices[t[0]]);
    EXPECT_GT(n.z(), 0.0) << "triangle faces down";
    area += 0.5 * n.z();
  }
  EXPECT_NEAR(area, (g.nx - 1) * (g.ny - 1) * g.cell_area_m2(), 1e-12);
  if (g.nx >= 2 && g.ny >= 2) {
    for (int u : uses) EXPECT_GE(u, 1) << "a vertex is in no triangle";
  }
}

TEST_F(HeightFieldIo, NpyRoundTripIsExact) {
  const HeightField f = wavy_field(13, 7);
  write_height_field_npy(path("h.npy"), f);
  const HeightField back = read_height_field_npy(path("h.npy"), f.grid());
  EXPECT_EQ(back.grid(), f.grid());
  EXPECT_EQ((back.heights() - f.heights()).abs().maxCoeff(), 0.0);
  // the file is ny rows x nx columns: row 0 is the smallest y
  const ArrayXXdR raw = read_npy_2d(path("h.npy"));
  ASSERT_EQ(raw.rows(), 7);
  ASSERT_EQ(raw.cols(), 13);
  EXPECT_EQ(raw(2, 5), f.at(5, 2));
}

TEST_F(HeightFieldIo, NpyShapeMismatchNamesBothShapes) {
  write_height_field_npy(path("h.npy"), wavy_field(5, 4));
  try {
    read_height_field_npy(path("h.npy"), Grid{4, 5, 0.05, 0, 0});
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(path("h.npy")), std::string::npos) << msg;
    EXPECT_NE(msg.find("(4, 5)"), std::string::npos) << msg;
    EXPECT_NE(msg.find("(5, 4)"), std::string::npos) << msg;
  }
}

TEST_F(HeightFieldIo, NonFiniteHeightsInNpyAreInputErrors) {
  ArrayXXdR a = ArrayXXdR::Zero(2, 3);
  a(1, 2) = std::nan("");
  write_npy_2d(path("nan.npy"), a);
  EXPECT_THROW(read_height_field_npy(path("nan.npy"), Grid{3, 2, 1.0, 0, 0}), InputError);
  a(1, 2) = -INFINITY;
  write_npy_2d(path("inf.npy"), a, NpyType::kFloat32);
  EXPECT_THROW(read_height_field_npy(path("inf.npy"), Grid{3, 2, 1.0, 0, 0}), InputError);
}

TEST_F(HeightFieldIo, ResampledFieldKeepsItsVolumeThroughNpy) {
  // the I/O path a coarse run takes: load, resample, save, load again
  const HeightField fine = wavy_field(24, 12);
  write_height_field_npy(path("fine.npy"), fine);
  const HeightField loaded = read_height_field_npy(path("fine.npy"), fine.grid());
  const HeightField coarse = resample_conservative(loaded, fine.grid().coarsened(4));
  write_height_field_npy(path("coarse.npy"), coarse);
  const HeightField back = read_height_field_npy(path("coarse.npy"), coarse.grid());
  EXPECT_NEAR(back.volume_m3(), fine.volume_m3(), 1e-12 * fine.heights().abs().sum() * fine.grid().cell_area_m2());
}

TEST_F(HeightFieldIo, ObjHasOneVertexPerCellAndTwoTrianglesPerQuad) {
  for (auto [nx, ny] : {std::pair{7, 5}, {1, 1}, {1, 6}, {2, 2}}) {
    const HeightField f = wavy_field(nx, ny);
    write_height_field_obj(path("h.obj"), f);
    expect_centre_mesh(parse_obj(path("h.obj")), f);
  }
}

TEST_F(HeightFieldIo, PlyBinaryAndAsciiHoldTheSameMesh) {
  for (auto [nx, ny] : {std::pair{7, 5}, {1, 1}, {3, 1}}) {
    const HeightField f = wavy_field(nx, ny);
    write_height_field_ply(path("b.ply"), f, PlyEncoding::kBinaryLittleEndian);
    write_height_field_ply(path("a.ply"), f, PlyEncoding::kAscii);
    const Mesh b = parse_ply(path("b.ply"));
    const Mesh a = parse_ply(path("a.ply"));
    expect_centre_mesh(b, f);
    expect_centre_mesh(a, f);
    EXPECT_EQ(a.faces, b.faces);
  }
}

TEST_F(HeightFieldIo, MeshMatchesBilinearSampleAtVerticesAndOnPlanes) {
  // on a plane the piecewise-linear mesh and the bilinear sample agree everywhere inside
  const Grid g{6, 4, 0.25, 1.0, -2.0};
  HeightField f(g);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) f.at(i, j) = 0.3 - 0.5 * g.centre_x(i) + 2.0 * g.centre_y(j);
  write_height_field_obj(path("p.obj"), f);
  const Mesh m = parse_obj(path("p.obj"));
  for (const auto& t : m.faces) {
    const Eigen::Vector3d c = (m.vertices[t[0]] + m.vertices[t[1]] + m.vertices[t[2]]) / 3.0;
    EXPECT_NEAR(f.sample(c.x(), c.y()), c.z(), 1e-12);
  }
  for (const Eigen::Vector3d& v : m.vertices) EXPECT_NEAR(f.sample(v.x(), v.y()), v.z(), 1e-12);
}

// ---- VTI ----

std::string attribute(const std::string& xml, const std::string& element, const std::string& name) {
  const std::size_t e = xml.find("<" + element + " ");
  if (e == std::string::npos) return "";
  const std::size_t close = xml.find('>', e);
  const std::string tag = xml.substr(e, close - e);
  const std::size_t a = tag.find(" " + name + "=\"");
  if (a == std::string::npos) return "";
  const std::size_t start = a + name.size() + 3;
  return tag.substr(start, tag.find('"', start) - start);
}

std::vector<double> numbers(const std::string& text) {
  std::istringstream in(text);
  std::vector<double> out;
  double v;
  while (in >> v) out.push_back(v);
  EXPECT_TRUE(in.eof()) << "not a number in: " << text.substr(0, 80);
  return out;
}

// The values of the DataArray called `name`, or empty if none.
std::vector<double> data_array(const std::string& xml, const std::string& name) {
  const std::size_t a = xml.find("Name=\"" + name + "\"");
  if (a == std::string::npos) return {};
  const std::size_t start = xml.find('>', a) + 1;
  const std::size_t end = xml.find("</DataArray>", start);
  return numbers(xml.substr(start, end - start));
}

TEST_F(HeightFieldIo, VtiIsAnImageWithOriginAtTheFirstCellCentre) {
  const HeightField f = wavy_field(7, 5);
  ArrayXXdR material(5, 7);
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i < 7; ++i) material(j, i) = i < 3 ? 0 : 2;
  write_height_field_vti(path("h.vti"), f, {{"material_id", material}});
  const std::string xml = read_all(path("h.vti"));
  EXPECT_EQ(attribute(xml, "VTKFile", "type"), "ImageData");
  EXPECT_EQ(attribute(xml, "ImageData", "WholeExtent"), "0 6 0 4 0 0");
  EXPECT_EQ(attribute(xml, "Piece", "Extent"), "0 6 0 4 0 0");
  const std::vector<double> origin = numbers(attribute(xml, "ImageData", "Origin"));
  const std::vector<double> spacing = numbers(attribute(xml, "ImageData", "Spacing"));
  ASSERT_EQ(origin.size(), 3u);
  ASSERT_EQ(spacing.size(), 3u);
  EXPECT_EQ(origin[0], f.grid().centre_x(0));
  EXPECT_EQ(origin[1], f.grid().centre_y(0));
  EXPECT_EQ(spacing[0], f.grid().cell_size_m);
  EXPECT_EQ(spacing[1], f.grid().cell_size_m);

  // point k = j * nx + i (x fastest), as VTK orders image points
  const std::vector<double> h = data_array(xml, "height_m");
  ASSERT_EQ(h.size(), 35u);
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i < 7; ++i) EXPECT_EQ(h[j * 7 + i], f.at(i, j));
  const std::vector<double> m = data_array(xml, "material_id");
  ASSERT_EQ(m.size(), 35u);
  EXPECT_EQ(m[7 + 2], 0);
  EXPECT_EQ(m[7 + 3], 2);
  EXPECT_EQ(attribute(xml, "PointData", "Scalars"), "height_m");

  // well-formed XML, if a Python is there to say so
  if (std::system("/usr/bin/python3 -c 'pass' 2>/dev/null") == 0) {
    const std::string cmd = "/usr/bin/python3 -c \"import xml.etree.ElementTree as E; E.parse('" + path("h.vti") +
                            "')\"";
    EXPECT_EQ(std::system(cmd.c_str()), 0);
  }
}

TEST_F(HeightFieldIo, VtiRejectsBadExtraArrays) {
  const HeightField f = wavy_field(4, 3);
  EXPECT_THROW(write_height_field_vti(path("a.vti"), f, {{"material_id", ArrayXXdR::Zero(4, 3)}}), InputError);
  EXPECT_THROW(write_height_field_vti(path("b.vti"), f, {{"bad\"name", ArrayXXdR::Zero(3, 4)}}), InputError);
  EXPECT_THROW(write_height_field_vti(path("c.vti"), f, {{"height_m", ArrayXXdR::Zero(3, 4)}}), InputError);
  EXPECT_FALSE(fs::exists(path("a.vti")));
}

TEST_F(HeightFieldIo, UnwritablePathIsAnInputError) {
  const HeightField f = wavy_field(2, 2);
  const std::string bad = path("no/such/dir/h");
  EXPECT_THROW(write_height_field_obj(bad + ".obj", f), InputError);
  EXPECT_THROW(write_height_field_ply(bad + ".ply", f), InputError);
  EXPECT_THROW(write_height_field_vti(bad + ".vti", f), InputError);
  EXPECT_THROW(write_height_field_npy(bad + ".npy", f), InputError);
}

}  // namespace
}  // namespace repose
