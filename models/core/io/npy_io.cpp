#include "models/core/io/npy_io.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <bit>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <tuple>
#include <limits>
#include <optional>
#include <string_view>

#include "models/core/base/error.h"
#include "models/core/base/memory_budget.h"
#include "models/core/io/input_file.h"

namespace repose {
namespace {

// The format: https://numpy.org/doc/stable/reference/generated/numpy.lib.format.html
constexpr char kMagic[] = "\x93NUMPY";
constexpr std::size_t kMagicSize = 6;
// Far more than any grid repose uses; larger shapes are rejected before allocating.
constexpr std::uint64_t kMaxElementCount = std::uint64_t{1} << 32;
// NumPy keeps headers small; a bigger one is a corrupt length field.
constexpr std::uint64_t kMaxHeaderBytes = std::uint64_t{1} << 20;

// Element types a height map may arrive in. Integers are converted exactly.
enum class Dtype { kF4, kF8, kI2, kU2, kI4, kU1 };

struct DtypeInfo {
  std::string_view descr_without_order;  // "f8"
  Dtype type;
  int size_bytes;
};
constexpr DtypeInfo kDtypes[] = {
    {"f4", Dtype::kF4, 4}, {"f8", Dtype::kF8, 8}, {"i2", Dtype::kI2, 2},
    {"u2", Dtype::kU2, 2}, {"i4", Dtype::kI4, 4}, {"u1", Dtype::kU1, 1},
};

struct NpyHeader {
  Dtype dtype = Dtype::kF8;
  int item_bytes = 8;
  bool fortran_order = false;
  std::vector<std::uint64_t> shape;
};

std::string shape_text(const std::vector<std::uint64_t>& shape) {
  if (shape.size() == 1) return fmt::format("({},)", shape[0]);
  return fmt::format("({})", fmt::join(shape, ", "));
}

// A tiny parser for the Python dict literal NumPy writes:
// {'descr': '<f8', 'fortran_order': False, 'shape': (3, 4), }
class HeaderParser {
 public:
  HeaderParser(std::string_view text, const std::string& path) : s_(text), path_(path) {}

  NpyHeader parse() {
    std::optional<std::string> descr;
    std::optional<bool> fortran;
    std::optional<std::vector<std::uint64_t>> shape;
    expect('{');
    while (!consume('}')) {
      const std::string key = string_literal();
      expect(':');
      if (key == "descr") {
        descr = descr_value();
      } else if (key == "fortran_order") {
        fortran = bool_value();
      } else if (key == "shape") {
        shape = shape_value();
      } else {
        fail(fmt::format("unexpected key '{}'", key));
      }
      if (!consume(',')) {
        expect('}');
        break;
      }
    }
    if (!descr) fail("no 'descr' key");
    if (!fortran) fail("no 'fortran_order' key");
    if (!shape) fail("no 'shape' key");
    NpyHeader h;
    h.fortran_order = *fortran;
    h.shape = *shape;
    set_dtype(*descr, h);
    return h;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(fmt::format("{}: bad .npy header: {} (header: {})", path_, what, trimmed()));
  }
  std::string trimmed() const {
    std::string t(s_);
    while (!t.empty() && std::isspace(static_cast<unsigned char>(t.back()))) t.pop_back();
    return t;
  }
  void skip_space() {
    while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_]))) ++pos_;
  }
  bool consume(char c) {
    skip_space();
    if (pos_ < s_.size() && s_[pos_] == c) {
      ++pos_;
      return true;
    }
    return false;
  }
  void expect(char c) {
    if (!consume(c)) fail(fmt::format("expected '{}' at character {}", c, pos_));
  }
  std::string string_literal() {
    skip_space();
    if (pos_ >= s_.size() || (s_[pos_] != '\'' && s_[pos_] != '"')) {
      fail(fmt::format("expected a quoted string at character {}", pos_));
    }
    const char quote = s_[pos_++];
    const std::size_t end = s_.find(quote, pos_);
    if (end == std::string_view::npos) fail("unterminated string");
    std::string out(s_.substr(pos_, end - pos_));
    pos_ = end + 1;
    return out;
  }
  std::string descr_value() {
    skip_space();
    if (pos_ < s_.size() && s_[pos_] == '[') fail("structured dtypes are not supported; expected a float array");
    return string_literal();
  }
  bool bool_value() {
    skip_space();
    for (std::string_view word : {"True", "False"}) {
      if (s_.substr(pos_, word.size()) == word) {
        pos_ += word.size();
        return word == "True";
      }
    }
    fail(fmt::format("'fortran_order' must be True or False (at character {})", pos_));
  }
  std::vector<std::uint64_t> shape_value() {
    expect('(');
    std::vector<std::uint64_t> dims;
    while (!consume(')')) {
      skip_space();
      std::uint64_t d = 0;
      bool any_digit = false;
      while (pos_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[pos_]))) {
        const std::uint64_t digit = static_cast<std::uint64_t>(s_[pos_] - '0');
        if (d > (std::numeric_limits<std::uint64_t>::max() - digit) / 10) fail("shape dimension too large");
        d = d * 10 + digit;
        any_digit = true;
        ++pos_;
      }
      // Python 2 era files may write long integers as 3L
      if (any_digit && pos_ < s_.size() && s_[pos_] == 'L') ++pos_;
      if (!any_digit) fail(fmt::format("expected a non-negative integer in 'shape' at character {}", pos_));
      dims.push_back(d);
      if (!consume(',')) {
        expect(')');
        break;
      }
    }
    return dims;
  }
  void set_dtype(const std::string& descr, NpyHeader& h) const {
    if (descr.size() < 2) fail(fmt::format("unknown dtype '{}'", descr));
    const char order = descr[0];
    const std::string_view rest = std::string_view(descr).substr(1);
    if (order == '>') {
      throw InputError(fmt::format("{}: big-endian dtype '{}' is not supported; save as little-endian ('<{}')",
                                   path_, descr, rest));
    }
    for (const DtypeInfo& d : kDtypes) {
      if (d.descr_without_order != rest) continue;
      const bool native_little = std::endian::native == std::endian::little;
      const bool order_ok = order == '<' || order == '|' || (order == '=' && native_little);
      if (!order_ok) break;
      h.dtype = d.type;
      h.item_bytes = d.size_bytes;
      return;
    }
    throw InputError(fmt::format(
        "{}: unsupported dtype '{}'; expected float32 ('<f4') or float64 ('<f8') (or '<i2', '<u2', '<i4', '|u1')",
        path_, descr));
  }

  std::string_view s_;
  const std::string& path_;
  std::size_t pos_ = 0;
};

std::uint64_t load_le(const unsigned char* p, int bytes) {
  std::uint64_t v = 0;
  for (int k = bytes - 1; k >= 0; --k) v = (v << 8) | p[k];
  return v;
}

double element_value(const unsigned char* p, Dtype t) {
  switch (t) {
    case Dtype::kF4: return std::bit_cast<float>(static_cast<std::uint32_t>(load_le(p, 4)));
    case Dtype::kF8: return std::bit_cast<double>(load_le(p, 8));
    case Dtype::kI2: return static_cast<std::int16_t>(static_cast<std::uint16_t>(load_le(p, 2)));
    case Dtype::kU2: return static_cast<std::uint16_t>(load_le(p, 2));
    case Dtype::kI4: return static_cast<std::int32_t>(static_cast<std::uint32_t>(load_le(p, 4)));
    case Dtype::kU1: return p[0];
  }
  REPOSE_DEMAND(false);
  return 0.0;
}

void store_le(std::uint64_t v, int bytes, std::string& out) {
  for (int k = 0; k < bytes; ++k) out.push_back(static_cast<char>((v >> (8 * k)) & 0xff));
}

std::string read_exactly(InputFile& in, std::uint64_t n, const char* what) {
  std::string buf(n, '\0');
  const std::size_t got = in.read(buf.data(), buf.size());
  if (got != n) throw InputError(fmt::format("{}: truncated: {} needs {} bytes, file has {}", in.path(), what, n, got));
  return buf;
}

// Rows and columns of a 1-D or 2-D shape; a 1-D array of n is 1 x n.
std::pair<std::uint64_t, std::uint64_t> rows_cols(const NpyHeader& h, const std::string& path) {
  if (h.shape.size() == 1) return {1, h.shape[0]};
  if (h.shape.size() == 2) return {h.shape[0], h.shape[1]};
  throw InputError(fmt::format("{}: expected a 1-D or 2-D array, got {}-D shape {}", path, h.shape.size(),
                               shape_text(h.shape)));
}

// double -> float32 as IEEE round-to-nearest does it (what NumPy's astype
// gives): finite values beyond float's range become +-inf or +-FLT_MAX
// instead of the undefined behaviour of an out-of-range static_cast.
float to_float32(double v) {
  constexpr double kFloatMax = std::numeric_limits<float>::max();
  if (!std::isfinite(v) || std::abs(v) <= kFloatMax) return static_cast<float>(v);
  // halfway between FLT_MAX and the next power of two, 2^128
  const double overflow_threshold = kFloatMax + std::ldexp(1.0, 127 - 24);
  const float magnitude =
      std::abs(v) >= overflow_threshold ? std::numeric_limits<float>::infinity() : std::numeric_limits<float>::max();
  return std::signbit(v) ? -magnitude : magnitude;
}

std::string write_header(const std::string& descr, const std::string& shape) {
  std::string dict = fmt::format("{{'descr': '{}', 'fortran_order': False, 'shape': {}, }}", descr, shape);
  // version 1.0: magic (6) + version (2) + length (2) + dict, padded with spaces and
  // ended by '\n' so that the data starts on a multiple of 64 bytes
  const std::size_t unpadded = kMagicSize + 2 + 2 + dict.size() + 1;
  dict.append((64 - unpadded % 64) % 64, ' ');
  dict.push_back('\n');
  std::string out(kMagic, kMagicSize);
  out.push_back('\x01');
  out.push_back('\x00');
  store_le(dict.size(), 2, out);
  return out + dict;
}

void write_npy(const std::string& path, const double* values, std::size_t count, const std::string& shape,
               NpyType type) {
  const bool f32 = type == NpyType::kFloat32;
  std::string bytes = write_header(f32 ? "<f4" : "<f8", shape);
  bytes.reserve(bytes.size() + count * (f32 ? 4 : 8));
  for (std::size_t k = 0; k < count; ++k) {
    if (f32) {
      store_le(std::bit_cast<std::uint32_t>(to_float32(values[k])), 4, bytes);
    } else {
      store_le(std::bit_cast<std::uint64_t>(values[k]), 8, bytes);
    }
  }
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw InputError(fmt::format("{}: cannot open for writing: {}", path, std::strerror(errno)));
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (!out) throw InputError(fmt::format("{}: write failed: {}", path, std::strerror(errno)));
}

// What the header says, checked against the file's size: everything needed
// to decode the data, known before a byte of it is read.
struct NpyLayout {
  NpyHeader header;
  std::uint64_t rows = 0;
  std::uint64_t cols = 0;
};

NpyLayout read_layout(InputFile& in) {
  const std::string& path = in.path();
  const std::string preamble = read_exactly(in, kMagicSize + 2, "the magic and version");
  if (preamble.compare(0, kMagicSize, kMagic, kMagicSize) != 0) {
    throw InputError(fmt::format("{}: not a .npy file (bad magic)", path));
  }
  const int major = static_cast<unsigned char>(preamble[kMagicSize]);
  const int minor = static_cast<unsigned char>(preamble[kMagicSize + 1]);
  if (major < 1 || major > 3 || minor != 0) {
    throw InputError(fmt::format("{}: unsupported .npy format version {}.{} (expected 1.0, 2.0 or 3.0)", path,
                                 major, minor));
  }
  const int length_bytes = major == 1 ? 2 : 4;
  const std::string length_field = read_exactly(in, length_bytes, "the header length");
  const std::uint64_t header_bytes =
      load_le(reinterpret_cast<const unsigned char*>(length_field.data()), length_bytes);
  if (header_bytes > kMaxHeaderBytes) {
    throw InputError(fmt::format("{}: bad .npy header: header length {} is implausibly large (corrupt file?)", path,
                                 header_bytes));
  }
  if (header_bytes > in.remaining()) {
    throw InputError(fmt::format("{}: truncated header: header says {} bytes, file has {} after the preamble", path,
                                 header_bytes, in.remaining()));
  }
  NpyLayout l;
  l.header = HeaderParser(read_exactly(in, header_bytes, "the header"), path).parse();
  std::tie(l.rows, l.cols) = rows_cols(l.header, path);
  // reject shapes that cannot fit before multiplying further or allocating
  constexpr auto kMaxIndex = static_cast<std::uint64_t>(std::numeric_limits<Eigen::Index>::max());
  if ((l.cols != 0 && l.rows > kMaxElementCount / l.cols) || l.rows * l.cols > kMaxElementCount ||
      l.rows > kMaxIndex || l.cols > kMaxIndex) {
    throw InputError(fmt::format("{}: shape {} is too large (more than {} elements)", path,
                                 shape_text(l.header.shape), kMaxElementCount));
  }
  const std::uint64_t data_bytes = l.rows * l.cols * static_cast<std::uint64_t>(l.header.item_bytes);
  if (in.remaining() < data_bytes) {
    throw InputError(fmt::format("{}: truncated: shape {} needs {} bytes of data, file has {}", path,
                                 shape_text(l.header.shape), data_bytes, in.remaining()));
  }
  if (in.remaining() > data_bytes) {
    throw InputError(fmt::format("{}: {} unexpected bytes after the data: shape {} needs {} bytes, file has {}",
                                 path, in.remaining() - data_bytes, shape_text(l.header.shape), data_bytes,
                                 in.remaining()));
  }
  return l;
}

// Decodes the data in chunks, so that the file's bytes are never held whole
// beside the array.
ArrayXXdR read_data(InputFile& in, const NpyLayout& l) {
  const NpyHeader& h = l.header;
  const std::uint64_t count = l.rows * l.cols;
  require_memory(memory_estimate::grid_bytes(l.cols, l.rows, 1),
                 fmt::format("{}: an array of {} x {} values", in.path(), l.rows, l.cols));
  ArrayXXdR a(static_cast<Eigen::Index>(l.rows), static_cast<Eigen::Index>(l.cols));
  constexpr std::uint64_t kChunkElements = 1 << 16;
  std::string chunk;
  for (std::uint64_t first = 0; first < count; first += kChunkElements) {
    const std::uint64_t n = std::min(kChunkElements, count - first);
    chunk = read_exactly(in, n * static_cast<std::uint64_t>(h.item_bytes), "the data");
    const auto* p = reinterpret_cast<const unsigned char*>(chunk.data());
    for (std::uint64_t k = first; k < first + n; ++k) {
      // C order: k = r * cols + c; Fortran order: k = c * rows + r
      const std::uint64_t r = h.fortran_order ? k % l.rows : k / l.cols;
      const std::uint64_t c = h.fortran_order ? k / l.rows : k % l.cols;
      a(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) =
          element_value(p + (k - first) * h.item_bytes, h.dtype);
    }
  }
  return a;
}

}  // namespace

NpyShape read_npy_shape(const std::string& path) {
  InputFile in = InputFile::open(path, input_kind::kNpy);
  const NpyLayout l = read_layout(in);
  return {l.rows, l.cols};
}

ArrayXXdR read_npy_2d(const std::string& path) {
  InputFile in = InputFile::open(path, input_kind::kNpy);
  const NpyLayout l = read_layout(in);
  return read_data(in, l);
}

ArrayXXdR read_npy_2d(const std::string& path, Eigen::Index rows, Eigen::Index cols) {
  REPOSE_DEMAND(rows >= 0 && cols >= 0);
  InputFile in = InputFile::open(path, input_kind::kNpy);
  const NpyLayout l = read_layout(in);
  if (l.rows != static_cast<std::uint64_t>(rows) || l.cols != static_cast<std::uint64_t>(cols)) {
    throw InputError(fmt::format("{}: its header declares {} rows x {} columns (shape {}); expected {} x {}", path,
                                 l.rows, l.cols, shape_text(l.header.shape), rows, cols));
  }
  return read_data(in, l);
}

void write_npy_2d(const std::string& path, const ArrayXXdR& a, NpyType type) {
  write_npy(path, a.data(), static_cast<std::size_t>(a.size()), fmt::format("({}, {})", a.rows(), a.cols()), type);
}

void write_npy_1d(const std::string& path, const std::vector<double>& a, NpyType type) {
  write_npy(path, a.data(), a.size(), fmt::format("({},)", a.size()), type);
}

}  // namespace repose
