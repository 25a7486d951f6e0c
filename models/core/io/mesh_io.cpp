#include "models/core/io/mesh_io.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <vector>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/core/base/memory_budget.h"
#include "models/core/io/input_file.h"

namespace repose {

namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const std::string& path, const std::string& reason) {
  throw InputError(fmt::format("{}: {}", path, reason));
}

[[noreturn]] void fail_at(const std::string& path, std::size_t line, const std::string& reason) {
  throw InputError(fmt::format("{}:{}: {}", path, line, reason));
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string read_bytes(const std::string& path) { return read_input_file(path, input_kind::kMesh); }

// A text mesh holds at most one vertex or face per 8 bytes ("v 0 0 0\n"):
// its arrays take at most about 8 times the text, and the text itself.
void require_memory_for_text(const std::string& path, const std::string& text) {
  require_memory(memory_estimate::product(text.size(), 9),
                 fmt::format("{}: a text mesh of {}", path, format_bytes(text.size())));
}

std::vector<std::string> split_words(const std::string& line) {
  std::vector<std::string> words;
  std::istringstream in(line);
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

std::optional<double> to_double(const std::string& s) {
  double x = 0.0;
  std::string_view v = s;
  if (!v.empty() && v.front() == '+') v.remove_prefix(1);
  const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), x, std::chars_format::general);
  if (v.empty() || ec != std::errc() || end != v.data() + v.size()) return std::nullopt;
  return x;
}

double coordinate(const std::string& path, std::size_t line, const std::string& word) {
  const auto x = to_double(word);
  if (!x) fail_at(path, line, fmt::format("'{}' is not a number", word));
  if (!std::isfinite(*x)) fail_at(path, line, fmt::format("non-finite coordinate {}", word));
  return *x;
}

TriangleMesh to_mesh(const std::vector<Eigen::Vector3d>& vertices, const std::vector<Eigen::Vector3i>& faces) {
  TriangleMesh m;
  m.V.resize(static_cast<Eigen::Index>(vertices.size()), 3);
  for (std::size_t k = 0; k < vertices.size(); ++k) m.V.row(static_cast<Eigen::Index>(k)) = vertices[k].transpose();
  m.F.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (std::size_t k = 0; k < faces.size(); ++k) m.F.row(static_cast<Eigen::Index>(k)) = faces[k].transpose();
  return m;
}

// ---- OBJ

// OBJ statements that carry no triangles; anything else unknown means the
// file is not what we think it is.
bool is_ignored_obj_statement(const std::string& w) {
  static const std::vector<std::string> ignored = {
      "vt", "vn", "vp", "o", "g", "s", "mg", "usemtl", "mtllib", "l", "p", "cstype", "deg", "bmat", "step",
      "curv", "curv2", "surf", "parm", "trim", "hole", "scrv", "sp", "end", "con", "bevel", "c_interp",
      "d_interp", "lod", "maplib", "usemap", "shadow_obj", "trace_obj", "ctech", "stech"};
  return std::find(ignored.begin(), ignored.end(), w) != ignored.end();
}

// "7", "7/2", "7//3", "7/2/3", "-1" -> a 0-based vertex index.
int obj_index(const std::string& path, std::size_t line, const std::string& word, std::size_t vertex_count) {
  const std::string first = word.substr(0, word.find('/'));
  long long k = 0;
  const auto [end, ec] = std::from_chars(first.data(), first.data() + first.size(), k);
  if (first.empty() || ec != std::errc() || end != first.data() + first.size()) {
    fail_at(path, line, fmt::format("face vertex '{}' is not an index", word));
  }
  const long long n = static_cast<long long>(vertex_count);
  const long long zero_based = k > 0 ? k - 1 : n + k;
  if (k == 0 || zero_based < 0 || zero_based >= n) {
    fail_at(path, line, fmt::format("face index {} out of range (1..{} vertices defined so far)", k, n));
  }
  return static_cast<int>(zero_based);
}

TriangleMesh parse_obj(const std::string& path, const std::string& text) {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Eigen::Vector3i> faces;
  std::istringstream in(text);
  std::size_t line_no = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_no;
    if (line.find('\0') != std::string::npos) fail_at(path, line_no, "binary data: not an OBJ file");
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    const auto words = split_words(line);
    if (words.empty()) continue;
    const std::string& what = words[0];
    if (what == "v") {
      if (words.size() != 4 && words.size() != 5 && words.size() != 7) {
        fail_at(path, line_no, "a vertex needs 3 coordinates");
      }
      vertices.emplace_back(coordinate(path, line_no, words[1]), coordinate(path, line_no, words[2]),
                            coordinate(path, line_no, words[3]));
    } else if (what == "f") {
      if (words.size() < 4) fail_at(path, line_no, "a face needs at least 3 vertices");
      std::vector<int> polygon;
      for (std::size_t k = 1; k < words.size(); ++k) polygon.push_back(obj_index(path, line_no, words[k], vertices.size()));
      for (std::size_t k = 1; k + 1 < polygon.size(); ++k) faces.emplace_back(polygon[0], polygon[k], polygon[k + 1]);
    } else if (!is_ignored_obj_statement(what)) {
      fail_at(path, line_no, fmt::format("unknown OBJ statement '{}': not an OBJ mesh", what.substr(0, 40)));
    }
  }
  return to_mesh(vertices, faces);
}

// ---- STL

// Welds identical vertices exactly so that shared edges become shared indices.
class VertexWelder {
 public:
  int index_of(const Eigen::Vector3d& p) {
    const auto [it, inserted] = index_.try_emplace({p.x(), p.y(), p.z()}, static_cast<int>(vertices_.size()));
    if (inserted) vertices_.push_back(p);
    return it->second;
  }
  const std::vector<Eigen::Vector3d>& vertices() const { return vertices_; }

 private:
  std::map<std::array<double, 3>, int> index_;
  std::vector<Eigen::Vector3d> vertices_;
};

std::uint32_t read_u32(const std::string& bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (int k = 3; k >= 0; --k) v = (v << 8) | static_cast<unsigned char>(bytes[at + static_cast<std::size_t>(k)]);
  return v;
}

float read_f32(const std::string& bytes, std::size_t at) { return std::bit_cast<float>(read_u32(bytes, at)); }

TriangleMesh parse_binary_stl(const std::string& path, const std::string& bytes) {
  const std::uint32_t count = read_u32(bytes, 80);
  require_memory(memory_estimate::triangle_mesh_bytes(count), fmt::format("{}: a mesh of {} triangles", path, count));
  VertexWelder welder;
  std::vector<Eigen::Vector3i> faces;
  faces.reserve(count);
  for (std::uint32_t t = 0; t < count; ++t) {
    const std::size_t base = 84 + 50 * static_cast<std::size_t>(t) + 12;  // skip the normal
    Eigen::Vector3i face;
    for (int c = 0; c < 3; ++c) {
      Eigen::Vector3d p;
      for (int d = 0; d < 3; ++d) p[d] = read_f32(bytes, base + 12 * static_cast<std::size_t>(c) + 4 * static_cast<std::size_t>(d));
      if (!p.allFinite()) fail(path, fmt::format("triangle {}: non-finite coordinate", t + 1));
      face[c] = welder.index_of(p);
    }
    faces.push_back(face);
  }
  return to_mesh(welder.vertices(), faces);
}

TriangleMesh parse_ascii_stl(const std::string& path, const std::string& text) {
  VertexWelder welder;
  std::vector<Eigen::Vector3i> faces;
  std::vector<int> loop;
  enum class Expect { kSolid, kFacetOrEnd, kOuterLoop, kVertexOrEndLoop, kEndFacet, kDone };
  Expect expect = Expect::kSolid;
  std::istringstream in(text);
  std::size_t line_no = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_no;
    const auto words = split_words(line);
    if (words.empty()) continue;
    const std::string w = lower(words[0]);
    switch (expect) {
      case Expect::kSolid:
        if (w != "solid") fail_at(path, line_no, "expected 'solid': not an STL file");
        expect = Expect::kFacetOrEnd;
        break;
      case Expect::kFacetOrEnd:
        if (w == "endsolid") {
          expect = Expect::kDone;
        } else if (w == "facet") {
          expect = Expect::kOuterLoop;
        } else {
          fail_at(path, line_no, fmt::format("expected 'facet' or 'endsolid', got '{}'", words[0].substr(0, 40)));
        }
        break;
      case Expect::kOuterLoop:
        if (w != "outer") fail_at(path, line_no, "expected 'outer loop'");
        loop.clear();
        expect = Expect::kVertexOrEndLoop;
        break;
      case Expect::kVertexOrEndLoop:
        if (w == "vertex") {
          if (words.size() != 4) fail_at(path, line_no, "a vertex needs 3 coordinates");
          loop.push_back(welder.index_of({coordinate(path, line_no, words[1]), coordinate(path, line_no, words[2]),
                                          coordinate(path, line_no, words[3])}));
        } else if (w == "endloop") {
          if (loop.size() < 3) fail_at(path, line_no, "a facet needs at least 3 vertices");
          for (std::size_t k = 1; k + 1 < loop.size(); ++k) faces.emplace_back(loop[0], loop[k], loop[k + 1]);
          expect = Expect::kEndFacet;
        } else {
          fail_at(path, line_no, fmt::format("expected 'vertex' or 'endloop', got '{}'", words[0].substr(0, 40)));
        }
        break;
      case Expect::kEndFacet:
        if (w != "endfacet") fail_at(path, line_no, "expected 'endfacet'");
        expect = Expect::kFacetOrEnd;
        break;
      case Expect::kDone:
        if (w != "solid") fail_at(path, line_no, "text after 'endsolid'");
        expect = Expect::kFacetOrEnd;  // several solids in one file
        break;
    }
  }
  if (expect == Expect::kSolid) fail(path, "empty STL file");
  if (expect != Expect::kDone) fail_at(path, line_no, "truncated ASCII STL (no 'endsolid')");
  return to_mesh(welder.vertices(), faces);
}

bool starts_with_solid(const std::string& bytes) {
  std::size_t k = 0;
  while (k < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[k]))) ++k;
  return bytes.compare(k, 5, "solid") == 0;
}

TriangleMesh parse_stl(const std::string& path, const std::string& bytes) {
  // binary when the size matches the header's count: some binary files start with "solid" too
  if (bytes.size() >= 84 && bytes.size() == 84 + 50 * static_cast<std::size_t>(read_u32(bytes, 80))) {
    return parse_binary_stl(path, bytes);
  }
  if (starts_with_solid(bytes) && bytes.find('\0') == std::string::npos) {
    require_memory_for_text(path, bytes);
    return parse_ascii_stl(path, bytes);
  }
  if (bytes.size() < 84) fail(path, fmt::format("not an STL file ({} bytes: too short for binary, no 'solid')", bytes.size()));
  fail(path, fmt::format("truncated or corrupt binary STL: header says {} triangles ({} bytes), file has {} bytes",
                         read_u32(bytes, 80), 84 + 50 * static_cast<std::size_t>(read_u32(bytes, 80)), bytes.size()));
}

void put_u32(std::string& out, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) out.push_back(static_cast<char>((v >> (8 * k)) & 0xff));
}

void put_f32(std::string& out, double v) { put_u32(out, std::bit_cast<std::uint32_t>(static_cast<float>(v))); }

void write_file(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) fail(path, "cannot be written");
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) fail(path, "write failed");
}

}  // namespace

TriangleMesh read_mesh(const std::string& path) {
  const std::string ext = lower(fs::path(path).extension().string());
  if (ext != ".obj" && ext != ".stl") fail(path, "expected a .obj or .stl mesh file");
  const std::string bytes = read_bytes(path);
  if (ext == ".stl") return parse_stl(path, bytes);
  require_memory_for_text(path, bytes);
  return parse_obj(path, bytes);
}

void write_stl(const std::string& path, const TriangleMesh& mesh) {
  std::string out(80, '\0');
  // The header's text ends in a newline: LIGGGHTS reads a mesh file's first
  // line as text to look for "solid", and a first line running on into the
  // triangle data fails there whenever that data holds a quote byte.
  const std::string header = "repose binary STL\n";
  std::copy(header.begin(), header.end(), out.begin());
  put_u32(out, static_cast<std::uint32_t>(mesh.F.rows()));
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0));
    const Eigen::Vector3d b = mesh.V.row(mesh.F(f, 1));
    const Eigen::Vector3d c = mesh.V.row(mesh.F(f, 2));
    const Eigen::Vector3d n = (b - a).cross(c - a).normalized();
    for (const Eigen::Vector3d& p : {n, a, b, c})
      for (int d = 0; d < 3; ++d) put_f32(out, std::isfinite(p[d]) ? p[d] : 0.0);
    out.append(2, '\0');  // attribute byte count
  }
  write_file(path, out);
}

void write_obj(const std::string& path, const TriangleMesh& mesh) {
  std::string out = "# repose OBJ\n";
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v) out += fmt::format("v {} {} {}\n", mesh.V(v, 0), mesh.V(v, 1), mesh.V(v, 2));
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    out += fmt::format("f {} {} {}\n", mesh.F(f, 0) + 1, mesh.F(f, 1) + 1, mesh.F(f, 2) + 1);
  }
  write_file(path, out);
}

void write_ply(const std::string& path, const TriangleMesh& mesh) {
  std::string out = fmt::format(
      "ply\nformat binary_little_endian 1.0\ncomment repose triangle mesh\n"
      "element vertex {}\nproperty double x\nproperty double y\nproperty double z\n"
      "element face {}\nproperty list uchar int vertex_indices\nend_header\n",
      mesh.V.rows(), mesh.F.rows());
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v) {
    for (int d = 0; d < 3; ++d) {
      const std::uint64_t bits = std::bit_cast<std::uint64_t>(mesh.V(v, d));
      for (int k = 0; k < 8; ++k) out.push_back(static_cast<char>((bits >> (8 * k)) & 0xff));
    }
  }
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    out.push_back('\x03');
    for (int d = 0; d < 3; ++d) put_u32(out, static_cast<std::uint32_t>(mesh.F(f, d)));
  }
  write_file(path, out);
}

}  // namespace repose
