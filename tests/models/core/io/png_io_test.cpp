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

}  // namespace
}  // namespace repose
