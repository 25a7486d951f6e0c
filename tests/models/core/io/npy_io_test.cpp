#include "models/core/io/npy_io.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>

#include "models/core/base/error.h"
#include "models/core/base/memory_budget.h"
#include <sys/stat.h>

#include "tests/support/temp_dir.h"

namespace repose {
namespace {

namespace fs = std::filesystem;

class NpyIo : public test_support::TempDirTest {};

using test_support::read_all;
using test_support::write_all;

void append_le(std::string& out, std::uint64_t v, int bytes) {
  for (int k = 0; k < bytes; ++k) out.push_back(static_cast<char>((v >> (8 * k)) & 0xff));
}

// A .npy file built by hand, independently of the writer under test.
std::string npy_file(const std::string& dict, int major = 1) {
  std::string out("\x93NUMPY", 6);
  out.push_back(static_cast<char>(major));
  out.push_back('\0');
  const int length_bytes = major == 1 ? 2 : 4;
  std::string header = dict;
  while ((6 + 2 + length_bytes + header.size() + 1) % 64 != 0) header.push_back(' ');
  header.push_back('\n');
  append_le(out, header.size(), length_bytes);
  return out + header;
}

std::string f8_data(std::initializer_list<double> values) {
  std::string out;
  for (double v : values) append_le(out, std::bit_cast<std::uint64_t>(v), 8);
  return out;
}

// Bit patterns compare NaN, -0.0 and denormals exactly.
void expect_bitwise_equal(const ArrayXXdR& a, const ArrayXXdR& b) {
  ASSERT_EQ(a.rows(), b.rows());
  ASSERT_EQ(a.cols(), b.cols());
  for (Eigen::Index r = 0; r < a.rows(); ++r)
    for (Eigen::Index c = 0; c < a.cols(); ++c)
      EXPECT_EQ(std::bit_cast<std::uint64_t>(a(r, c)), std::bit_cast<std::uint64_t>(b(r, c)))
          << r << "," << c << ": " << a(r, c) << " vs " << b(r, c);
}

// Expects an InputError whose message names the file and contains `what`.
void expect_input_error(const std::string& path, const std::string& what) {
  try {
    read_npy_2d(path);
    ADD_FAILURE() << "no error for " << path;
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(path), std::string::npos) << msg;
    EXPECT_NE(msg.find(what), std::string::npos) << msg;
  }
}

ArrayXXdR varied_values(int rows, int cols) {
  const double specials[] = {-0.0,
                             -1.5,
                             std::numeric_limits<double>::denorm_min(),
                             -std::numeric_limits<double>::denorm_min() * 3,
                             std::numeric_limits<double>::min() / 7,
                             std::numeric_limits<double>::max(),
                             std::numeric_limits<double>::lowest(),
                             std::numeric_limits<double>::infinity(),
                             -std::numeric_limits<double>::infinity(),
                             std::numeric_limits<double>::quiet_NaN()};
  ArrayXXdR a(rows, cols);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      const int k = r * cols + c;
      a(r, c) = k < 10 ? specials[k] : std::sin(0.37 * k) * std::pow(10.0, (k % 9) - 4);
    }
  return a;
}

TEST_F(NpyIo, Float64RoundTripIsBitExact) {
  for (auto [rows, cols] : {std::pair{1, 1}, {7, 13}, {13, 7}, {1, 20}, {20, 1}}) {
    const ArrayXXdR a = varied_values(rows, cols);
    write_npy_2d(path("a.npy"), a, NpyType::kFloat64);
    expect_bitwise_equal(read_npy_2d(path("a.npy")), a);
  }
}

TEST_F(NpyIo, Float32RoundTripRoundsToNearestFloat) {
  const ArrayXXdR a = varied_values(7, 13);
  write_npy_2d(path("a.npy"), a, NpyType::kFloat32);
  ArrayXXdR expected(7, 13);
  for (int r = 0; r < 7; ++r)
    for (int c = 0; c < 13; ++c) {
      const double v = a(r, c);
      // beyond float's range, round-to-nearest overflows to infinity
      const bool overflows = std::isfinite(v) && std::abs(v) > 2 * static_cast<double>(FLT_MAX);
      expected(r, c) = overflows ? std::copysign(INFINITY, v) : static_cast<double>(static_cast<float>(v));
    }
  EXPECT_EQ(expected(0, 5), INFINITY);  // the double max is among the values
  expect_bitwise_equal(read_npy_2d(path("a.npy")), expected);
  // a float32 file holds 4 bytes per element
  EXPECT_EQ(fs::file_size(path("a.npy")) % 64, (7 * 13 * 4) % 64);
  // float denormals survive
  ArrayXXdR d(1, 2);
  d << std::numeric_limits<float>::denorm_min(), -std::numeric_limits<float>::denorm_min() * 5;
  write_npy_2d(path("d.npy"), d, NpyType::kFloat32);
  expect_bitwise_equal(read_npy_2d(path("d.npy")), d);
  // just past FLT_MAX rounds back to it; at the halfway point to 2^128 it overflows
  ArrayXXdR edge(1, 3);
  edge << static_cast<double>(FLT_MAX) * (1 + 1e-9), -static_cast<double>(FLT_MAX) * (1 + 1e-9),
      static_cast<double>(FLT_MAX) + std::ldexp(1.0, 103);
  write_npy_2d(path("e.npy"), edge, NpyType::kFloat32);
  const ArrayXXdR e = read_npy_2d(path("e.npy"));
  EXPECT_EQ(e(0, 0), FLT_MAX);
  EXPECT_EQ(e(0, 1), -FLT_MAX);
  EXPECT_EQ(e(0, 2), INFINITY);
}

TEST_F(NpyIo, OneDimensionalArrayReadsAsOneRow) {
  const std::vector<double> v = {3.0, -2.5, 1e-300, 7.0};
  write_npy_1d(path("v.npy"), v);
  const ArrayXXdR a = read_npy_2d(path("v.npy"));
  ASSERT_EQ(a.rows(), 1);
  ASSERT_EQ(a.cols(), 4);
  for (int k = 0; k < 4; ++k) EXPECT_EQ(a(0, k), v[k]);
  EXPECT_NE(read_all(path("v.npy")).find("'shape': (4,)"), std::string::npos);
}

TEST_F(NpyIo, WrittenHeaderIsVersion1PaddedTo64Bytes) {
  for (auto [rows, cols] : {std::pair{1, 1}, {7, 13}, {123456, 0}}) {
    write_npy_2d(path("a.npy"), ArrayXXdR::Zero(rows, cols));
    const std::string bytes = read_all(path("a.npy"));
    ASSERT_GE(bytes.size(), 10u);
    EXPECT_EQ(bytes.substr(0, 8), std::string("\x93NUMPY\x01\x00", 8));
    const std::size_t header_len = static_cast<unsigned char>(bytes[8]) | (static_cast<unsigned char>(bytes[9]) << 8);
    const std::size_t data_offset = 10 + header_len;
    EXPECT_EQ(data_offset % 64, 0u);
    EXPECT_EQ(bytes[data_offset - 1], '\n');
    EXPECT_EQ(bytes.size(), data_offset + static_cast<std::size_t>(rows) * cols * 8);
  }
}

TEST_F(NpyIo, ReadsFortranOrder) {
  // the 2 x 3 matrix [[1 2 3] [4 5 6]] stored column by column
  write_all(path("f.npy"), npy_file("{'descr': '<f8', 'fortran_order': True, 'shape': (2, 3), }") +
                                 f8_data({1, 4, 2, 5, 3, 6}));
  const ArrayXXdR a = read_npy_2d(path("f.npy"));
  ASSERT_EQ(a.rows(), 2);
  ASSERT_EQ(a.cols(), 3);
  for (int r = 0; r < 2; ++r)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(a(r, c), 1 + 3 * r + c);
}

TEST_F(NpyIo, ReadsVersions2And3AndDoubleQuotes) {
  for (int major : {2, 3}) {
    const std::string dict = "{\"descr\": \"<f8\", \"fortran_order\": False, \"shape\": (1, 2)}";
    write_all(path("v.npy"), npy_file(dict, major) + f8_data({-1, 2}));
    const ArrayXXdR a = read_npy_2d(path("v.npy"));
    ASSERT_EQ(a.size(), 2);
    EXPECT_EQ(a(0, 0), -1.0);
    EXPECT_EQ(a(0, 1), 2.0);
  }
}

TEST_F(NpyIo, ReadsSmallIntegerDtypesExactly) {
  std::string data;
  for (int v : {-32768, -1, 0, 32767}) append_le(data, static_cast<std::uint16_t>(v), 2);
  write_all(path("i2.npy"), npy_file("{'descr': '<i2', 'fortran_order': False, 'shape': (2, 2), }") + data);
  const ArrayXXdR a = read_npy_2d(path("i2.npy"));
  EXPECT_EQ(a(0, 0), -32768);
  EXPECT_EQ(a(0, 1), -1);
  EXPECT_EQ(a(1, 1), 32767);
  data.clear();
  for (int v : {0, 1, 65535}) append_le(data, static_cast<std::uint16_t>(v), 2);
  write_all(path("u2.npy"), npy_file("{'descr': '<u2', 'fortran_order': False, 'shape': (3,), }") + data);
  EXPECT_EQ(read_npy_2d(path("u2.npy"))(0, 2), 65535);
}

TEST_F(NpyIo, ReadsFilesWrittenByNumPy) {
  if (std::system("/usr/bin/python3 -c 'import numpy' 2>/dev/null") != 0) {
    GTEST_SKIP() << "/usr/bin/python3 has no numpy";
  }
  // value(r, c) = (r - 2.5) * 10^(c - 3) + c / 7, computed in both languages
  const std::string script =
      "import numpy as np\n"
      "d = '" + dir_.path.string() + "'\n"
      "r, c = np.meshgrid(np.arange(5), np.arange(9), indexing='ij')\n"
      "a = (r - 2.5) * 10.0 ** (c - 3) + c / 7\n"
      "np.save(d + '/c64.npy', a)\n"
      "np.save(d + '/c32.npy', a.astype(np.float32))\n"
      "np.save(d + '/fortran.npy', np.asfortranarray(a))\n"
      "np.save(d + '/one_d.npy', a[3])\n"
      "with open(d + '/v2.npy', 'wb') as f: np.lib.format.write_array(f, a, version=(2, 0))\n"
      "np.save(d + '/big_endian.npy', a.astype('>f8'))\n";
  write_all(path("make.py"), script);
  ASSERT_EQ(std::system(("/usr/bin/python3 " + path("make.py")).c_str()), 0);

  ArrayXXdR expected(5, 9);
  for (int r = 0; r < 5; ++r)
    for (int c = 0; c < 9; ++c) expected(r, c) = (r - 2.5) * std::pow(10.0, c - 3) + c / 7.0;
  for (const char* name : {"c64.npy", "fortran.npy", "v2.npy"}) {
    const ArrayXXdR a = read_npy_2d(path(name));
    ASSERT_EQ(a.rows(), 5) << name;
    ASSERT_EQ(a.cols(), 9) << name;
    // pow may differ from NumPy's in the last bit
    for (int r = 0; r < 5; ++r)
      for (int c = 0; c < 9; ++c) EXPECT_NEAR(a(r, c), expected(r, c), 1e-15 * std::abs(expected(r, c))) << name;
  }
  const ArrayXXdR f = read_npy_2d(path("c32.npy"));
  EXPECT_NEAR((f - expected).abs().maxCoeff() / expected.abs().maxCoeff(), 0.0, 1e-7);
  const ArrayXXdR row = read_npy_2d(path("one_d.npy"));
  ASSERT_EQ(row.rows(), 1);
  ASSERT_EQ(row.cols(), 9);
  EXPECT_NEAR(row(0, 4), expected(3, 4), 1e-15);
  expect_input_error(path("big_endian.npy"), "big-endian");

  // and NumPy reads what we write
  write_npy_2d(path("ours.npy"), expected, NpyType::kFloat32);
  const std::string check = "import numpy as np\na = np.load('" + path("ours.npy") +
                            "')\nassert a.dtype == np.float32 and a.shape == (5, 9), (a.dtype, a.shape)\n"
                            "assert a[4, 8] == np.float32(1.5 * 10.0 ** 5 + 8 / 7)\n";
  write_all(path("check.py"), check);
  EXPECT_EQ(std::system(("/usr/bin/python3 " + path("check.py")).c_str()), 0);
}

TEST_F(NpyIo, BadMagicIsAnInputError) {
  write_all(path("bad.npy"), "PK\x03\x04 this is a zip file, not an array");
  expect_input_error(path("bad.npy"), "not a .npy file (bad magic)");
}

TEST_F(NpyIo, EmptyAndMissingFilesAreInputErrors) {
  write_all(path("empty.npy"), "");
  expect_input_error(path("empty.npy"), "truncated");
  expect_input_error(path("missing.npy"), "no such file");
}

TEST_F(NpyIo, TruncatedHeaderIsAnInputError) {
  const std::string full = npy_file("{'descr': '<f8', 'fortran_order': False, 'shape': (3, 4), }");
  write_all(path("h.npy"), full.substr(0, 30));
  expect_input_error(path("h.npy"), "truncated header");
}

TEST_F(NpyIo, TruncatedDataNamesShapeAndSizes) {
  write_all(path("d.npy"),
              npy_file("{'descr': '<f8', 'fortran_order': False, 'shape': (3, 4), }") + std::string(40, '\0'));
  expect_input_error(path("d.npy"), "truncated: shape (3, 4) needs 96 bytes of data, file has 40");
}

TEST_F(NpyIo, TrailingBytesAreAnInputError) {
  write_all(path("d.npy"),
              npy_file("{'descr': '<f8', 'fortran_order': False, 'shape': (1, 1), }") + std::string(16, '\0'));
  expect_input_error(path("d.npy"), "unexpected bytes");
}

TEST_F(NpyIo, UnsupportedDtypesAreInputErrors) {
  for (const char* descr : {"<c16", "<U4", "|b1", "<f2", "O"}) {
    write_all(path("t.npy"), npy_file(std::string("{'descr': '") + descr +
                                        "', 'fortran_order': False, 'shape': (1, 1), }") +
                                   std::string(16, '\0'));
    expect_input_error(path("t.npy"), "dtype");
  }
  write_all(path("s.npy"),
              npy_file("{'descr': [('a', '<f8')], 'fortran_order': False, 'shape': (1,), }") + std::string(8, '\0'));
  expect_input_error(path("s.npy"), "structured");
  write_all(path("b.npy"), npy_file("{'descr': '>f8', 'fortran_order': False, 'shape': (1,), }") + f8_data({1}));
  expect_input_error(path("b.npy"), "big-endian");
}

TEST_F(NpyIo, ThreeDimensionalShapeIsAnInputError) {
  write_all(path("3d.npy"),
              npy_file("{'descr': '<f8', 'fortran_order': False, 'shape': (2, 2, 2), }") + std::string(64, '\0'));
  expect_input_error(path("3d.npy"), "got 3-D shape (2, 2, 2)");
  write_all(path("0d.npy"), npy_file("{'descr': '<f8', 'fortran_order': False, 'shape': (), }") + f8_data({1}));
  expect_input_error(path("0d.npy"), "0-D");
}

TEST_F(NpyIo, HugeShapeIsRejectedBeforeAllocating) {
  // would need exabytes: must fail on the shape, not on an allocation
  write_all(path("huge.npy"),
              npy_file("{'descr': '<f8', 'fortran_order': False, 'shape': (4000000000, 4000000000), }") +
                  f8_data({1}));
  expect_input_error(path("huge.npy"), "too large");
  write_all(path("overflow.npy"),
              npy_file("{'descr': '<f8', 'fortran_order': False, 'shape': (99999999999999999999999, 1), }"));
  expect_input_error(path("overflow.npy"), "shape");
  // within the element limit but far more than the file holds
  write_all(path("big.npy"),
              npy_file("{'descr': '<f8', 'fortran_order': False, 'shape': (60000, 60000), }") + f8_data({1}));
  expect_input_error(path("big.npy"), "truncated: shape (60000, 60000) needs 28800000000 bytes of data, file has 8");
}

TEST_F(NpyIo, MalformedHeadersAreInputErrors) {
  for (const char* dict : {"{'descr': '<f8', 'shape': (1, 1), }", "{'descr': '<f8', 'fortran_order': False}",
                           "{'descr': '<f8', 'fortran_order': maybe, 'shape': (1, 1), }",
                           "{'descr': '<f8', 'fortran_order': False, 'shape': (1, -1), }",
                           "{'descr': '<f8', 'fortran_order': False, 'shape': (1, 1), 'extra': 1}", "not a dict"}) {
    write_all(path("m.npy"), npy_file(dict) + f8_data({1}));
    expect_input_error(path("m.npy"), "bad .npy header");
  }
  std::string bad_version = npy_file("{'descr': '<f8', 'fortran_order': False, 'shape': (1,), }") + f8_data({1});
  bad_version[6] = 4;
  write_all(path("v.npy"), bad_version);
  expect_input_error(path("v.npy"), "version 4.0");
}

// The shape is checked from the header, before the data is read or memory
// allocated: with a budget of one byte, the wrong shape is what is reported.
TEST_F(NpyIo, ExpectedShapeIsCheckedFromTheHeaderBeforeDecoding) {
  write_all(path("a.npy"), npy_file("{'descr': '<f8', 'fortran_order': False, 'shape': (3, 4), }") +
                               f8_data({1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12}));
  const NpyShape shape = read_npy_shape(path("a.npy"));
  EXPECT_EQ(shape.rows, 3u);
  EXPECT_EQ(shape.cols, 4u);
  EXPECT_EQ(read_npy_2d(path("a.npy"), 3, 4)(2, 3), 12.0);
  set_memory_budget_bytes(1);
  try {
    (void)read_npy_2d(path("a.npy"), 4, 3);
    ADD_FAILURE() << "a 3 x 4 array was accepted as 4 x 3";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("its header declares 3 rows x 4 columns (shape (3, 4)); expected 4 x 3"),
              std::string::npos)
        << e.what();
  }
  // without an expected shape the budget refuses the 96 bytes
  expect_input_error(path("a.npy"), "needs about 96 bytes of memory, more than the memory budget of 1 bytes");
  set_memory_budget_bytes(std::nullopt);
}

TEST_F(NpyIo, FifoAndDeviceAreRefusedWithoutBlocking) {
  ASSERT_EQ(::mkfifo(path("pipe.npy").c_str(), 0600), 0);
  expect_input_error(path("pipe.npy"), "is a FIFO (named pipe), not a regular .npy file");
  expect_input_error("/dev/zero", "is a character device, not a regular .npy file");
}

}  // namespace
}  // namespace repose
