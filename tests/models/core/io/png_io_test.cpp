#include "models/core/io/png_io.h"

#include <gtest/gtest.h>
#include <png.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "models/core/base/error.h"
#include "models/core/base/memory_budget.h"
#include <sys/stat.h>
#include <zlib.h>

#include "tests/support/temp_dir.h"

namespace repose {
namespace {

namespace fs = std::filesystem;

class PngIo : public test_support::TempDirTest {};

using test_support::read_all;
using test_support::write_all;

// Writes a grey or colour PNG with libpng's simplified API, independently of
// the writer under test. `pixels` holds rows top to bottom.
void write_reference_png(const std::string& path, int width, int height, png_uint_32 format,
                         const std::vector<std::uint8_t>& pixels) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = static_cast<png_uint_32>(width);
  image.height = static_cast<png_uint_32>(height);
  image.format = format;
  ASSERT_NE(png_image_write_to_file(&image, path.c_str(), 0, pixels.data(), 0, nullptr), 0) << image.message;
}

void expect_input_error(const std::string& path, const std::string& what) {
  try {
    read_png16(path);
    ADD_FAILURE() << "no error for " << path;
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(path), std::string::npos) << msg;
    EXPECT_NE(msg.find(what), std::string::npos) << msg;
  }
}

ArrayXXdR ramp16(int rows, int cols) {
  ArrayXXdR a(rows, cols);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) a(r, c) = (r * 7919 + c * 104729) % 65536;
  a(0, 0) = 0;
  a(rows - 1, cols - 1) = 65535;
  return a;
}

TEST_F(PngIo, SixteenBitRoundTripIsExact) {
  for (auto [rows, cols] : {std::pair{1, 1}, {7, 13}, {64, 3}}) {
    const ArrayXXdR a = ramp16(rows, cols);
    write_png16(path("h.png"), a);
    const ArrayXXdR b = read_png16(path("h.png"));
    ASSERT_EQ(b.rows(), rows);
    ASSERT_EQ(b.cols(), cols);
    EXPECT_EQ((a - b).abs().maxCoeff(), 0.0);
  }
}

TEST_F(PngIo, WritingRoundsAndClamps) {
  ArrayXXdR a(1, 5);
  a << -3.0, 0.4, 0.6, 65534.7, 1e9;
  write_png16(path("c.png"), a);
  const ArrayXXdR b = read_png16(path("c.png"));
  EXPECT_EQ(b(0, 0), 0);
  EXPECT_EQ(b(0, 1), 0);
  EXPECT_EQ(b(0, 2), 1);
  EXPECT_EQ(b(0, 3), 65535);
  EXPECT_EQ(b(0, 4), 65535);
  a(0, 2) = std::nan("");
  EXPECT_THROW(write_png16(path("n.png"), a), InputError);
}

TEST_F(PngIo, TopImageRowIsLargestY) {
  // 2 rows x 3 columns: array row 0 (smallest y) must be the bottom image row
  ArrayXXdR a(2, 3);
  a << 1, 2, 3, 40000, 50000, 60000;
  write_png16(path("o.png"), a);
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  ASSERT_NE(png_image_begin_read_from_file(&image, path("o.png").c_str()), 0);
  image.format = PNG_FORMAT_LINEAR_Y;  // 16-bit grey, host order
  std::vector<std::uint16_t> pixels(6);
  ASSERT_NE(png_image_finish_read(&image, nullptr, pixels.data(), 0, nullptr), 0) << image.message;
  EXPECT_EQ(image.width, 3u);
  EXPECT_EQ(image.height, 2u);
  // first (top) row of the file = array row 1; the reader may apply a gamma
  // curve, which keeps the order of the values
  EXPECT_LT(pixels[0], pixels[1]);
  EXPECT_LT(pixels[1], pixels[2]);
  EXPECT_LT(pixels[3], pixels[4]);
  EXPECT_LT(pixels[5], pixels[0]);

  // and reading an image written by someone else puts its top row last
  write_reference_png(path("r.png"), 2, 2, PNG_FORMAT_GRAY, {10, 20, 30, 40});
  const ArrayXXdR b = read_png16(path("r.png"));
  EXPECT_EQ(b(1, 0), 10 * 257);
  EXPECT_EQ(b(1, 1), 20 * 257);
  EXPECT_EQ(b(0, 0), 30 * 257);
  EXPECT_EQ(b(0, 1), 40 * 257);
}

TEST_F(PngIo, EightBitGreyIsScaledToSixteenBits) {
  write_reference_png(path("g8.png"), 3, 1, PNG_FORMAT_GRAY, {0, 128, 255});
  const ArrayXXdR b = read_png16(path("g8.png"));
  ASSERT_EQ(b.rows(), 1);
  ASSERT_EQ(b.cols(), 3);
  EXPECT_EQ(b(0, 0), 0);
  EXPECT_EQ(b(0, 1), 128 * 257);
  EXPECT_EQ(b(0, 2), 65535);
}

TEST_F(PngIo, ColourImagesAreRejectedWithTheirType) {
  write_reference_png(path("rgb.png"), 2, 1, PNG_FORMAT_RGB, {1, 2, 3, 4, 5, 6});
  expect_input_error(path("rgb.png"), "RGB");
  write_reference_png(path("ga.png"), 1, 1, PNG_FORMAT_GA, {1, 2});
  expect_input_error(path("ga.png"), "grey+alpha");
}

TEST_F(PngIo, TruncatedPngIsAnInputError) {
  write_png16(path("full.png"), ramp16(40, 50));
  const std::string bytes = read_all(path("full.png"));
  for (std::size_t keep : {std::size_t{8}, std::size_t{20}, std::size_t{60}, bytes.size() / 2, bytes.size() - 13}) {
    write_all(path("cut.png"), bytes.substr(0, keep));
    expect_input_error(path("cut.png"), "truncated PNG");
  }
  write_all(path("short.png"), bytes.substr(0, 5));
  expect_input_error(path("short.png"), "not a PNG file");
}

TEST_F(PngIo, CorruptDataIsAnInputError) {
  write_png16(path("full.png"), ramp16(40, 50));
  std::string bytes = read_all(path("full.png"));
  for (std::size_t k = bytes.size() / 2; k < bytes.size() / 2 + 16; ++k) bytes[k] = static_cast<char>(bytes[k] ^ 0x5a);
  write_all(path("bad.png"), bytes);
  expect_input_error(path("bad.png"), "PNG");
}

TEST_F(PngIo, NotAPngOrMissingIsAnInputError) {
  write_all(path("text.png"), "hello, this is not an image");
  expect_input_error(path("text.png"), "not a PNG file");
  expect_input_error(path("missing.png"), "no such file");
}

TEST_F(PngIo, RgbRoundTripIsExact) {
  RgbImage image;
  image.width = 5;
  image.height = 3;
  for (int k = 0; k < 5 * 3 * 3; ++k) image.rgb.push_back(static_cast<std::uint8_t>((k * 37) % 256));
  write_png_rgb(path("c.png"), image);
  const RgbImage back = read_png_rgb(path("c.png"));
  EXPECT_EQ(back.width, 5);
  EXPECT_EQ(back.height, 3);
  EXPECT_EQ(back.rgb, image.rgb);

  // row 0 is the top: an independent reader sees the same first pixel
  png_image ref{};
  ref.version = PNG_IMAGE_VERSION;
  ASSERT_NE(png_image_begin_read_from_file(&ref, path("c.png").c_str()), 0);
  ref.format = PNG_FORMAT_RGB;
  std::vector<std::uint8_t> pixels(PNG_IMAGE_SIZE(ref));
  ASSERT_NE(png_image_finish_read(&ref, nullptr, pixels.data(), 0, nullptr), 0);
  EXPECT_EQ(pixels, image.rgb);
}

TEST_F(PngIo, RgbReaderConvertsGrey) {
  write_reference_png(path("g.png"), 2, 1, PNG_FORMAT_GRAY, {7, 200});
  const RgbImage back = read_png_rgb(path("g.png"));
  EXPECT_EQ(back.rgb, (std::vector<std::uint8_t>{7, 7, 7, 200, 200, 200}));
}

// A PNG whose header declares width x height 16-bit grey pixels, followed by
// one IDAT of a few compressed zero rows and IEND: a few hundred bytes that
// would decode into width * height * 2 bytes of pixels.
std::string png_declaring(std::uint32_t width, std::uint32_t height) {
  auto u32 = [](std::uint32_t v) {
    return std::string{static_cast<char>(v >> 24), static_cast<char>(v >> 16), static_cast<char>(v >> 8),
                       static_cast<char>(v)};
  };
  auto chunk = [&](const std::string& type, const std::string& data) {
    const std::string body = type + data;
    const auto crc = static_cast<std::uint32_t>(
        ::crc32(0, reinterpret_cast<const Bytef*>(body.data()), static_cast<uInt>(body.size())));
    return u32(static_cast<std::uint32_t>(data.size())) + body + u32(crc);
  };
  const std::string ihdr = u32(width) + u32(height) + std::string{16, 0, 0, 0, 0};  // 16-bit grey
  std::string raw(4 * (1 + 2 * static_cast<std::size_t>(width)), '\0');               // 4 rows, filter 0
  uLongf packed_size = compressBound(static_cast<uLong>(raw.size()));
  std::string packed(packed_size, '\0');
  ::compress(reinterpret_cast<Bytef*>(packed.data()), &packed_size, reinterpret_cast<const Bytef*>(raw.data()),
             static_cast<uLong>(raw.size()));
  packed.resize(packed_size);
  return std::string("\x89PNG\r\n\x1a\n", 8) + chunk("IHDR", ihdr) + chunk("IDAT", packed) + chunk("IEND", "");
}

// The case: a small PNG whose header says 16384^2 for a 32^2 grid was
// decoded (2.6 GB) before its shape was compared. Now the header decides:
// with a budget of one byte, the wrong size is what is reported.
TEST_F(PngIo, ExpectedSizeIsCheckedFromTheHeaderBeforeDecoding) {
  write_all(path("huge.png"), png_declaring(16384, 16384));
  const PngSize size = read_png_size(path("huge.png"));
  EXPECT_EQ(size.width, 16384u);
  EXPECT_EQ(size.height, 16384u);
  set_memory_budget_bytes(1);
  try {
    (void)read_png16(path("huge.png"), 32, 32);
    ADD_FAILURE() << "a 16384^2 PNG was accepted for a 32^2 grid";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("its header declares 16384 x 16384 pixels (width x height); expected 32 x 32"),
              std::string::npos)
        << e.what();
  }
  set_memory_budget_bytes(std::nullopt);
}

TEST_F(PngIo, DecodingBeyondTheMemoryBudgetIsRefusedWithTheEstimate) {
  write_all(path("huge.png"), png_declaring(16384, 16384));
  set_memory_budget_bytes(std::uint64_t{64} << 20);
  // 16384^2 pixels: 2 bytes decoded plus 8 as a double each
  expect_input_error(path("huge.png"), "a PNG of 16384 x 16384 pixels needs about 2.5 GB of memory");
  set_memory_budget_bytes(std::nullopt);
  // the same construction at a size that fits decodes: the refusals above are the size's
  write_all(path("small.png"), png_declaring(5, 4));
  const ArrayXXdR small = read_png16(path("small.png"), 4, 5);
  EXPECT_EQ(small.rows(), 4);
  EXPECT_EQ(small.cols(), 5);
  EXPECT_EQ(small.abs().maxCoeff(), 0.0);
}

TEST_F(PngIo, FifoAndDeviceAreRefusedWithoutBlocking) {
  ASSERT_EQ(::mkfifo(path("pipe.png").c_str(), 0600), 0);
  expect_input_error(path("pipe.png"), "is a FIFO (named pipe), not a regular PNG file");
  expect_input_error("/dev/zero", "is a character device, not a regular PNG file");
}

}  // namespace
}  // namespace repose
