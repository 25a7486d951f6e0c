#include "models/core/io/png_io.h"

#include <png.h>

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <optional>

#include "models/core/base/error.h"
#include "models/core/base/memory_budget.h"
#include "models/core/io/input_file.h"

namespace repose {
namespace {

// libpng reports errors by longjmp. A longjmp must not skip a C++ destructor,
// so every function below that calls setjmp holds only trivially destructible
// locals (plain pointers and integers) and returns an error flag; the C++
// objects (buffers, the RAII guard that frees libpng's structs) live in the
// callers, which longjmp never crosses.

// Larger images are rejected before allocating (2^28 pixels = 16384^2).
constexpr std::uint64_t kMaxPixels = std::uint64_t{1} << 28;

struct PngErrorSink {
  char message[256] = {0};
};

extern "C" void png_error_to_sink(png_structp png, png_const_charp msg) {
  auto* sink = static_cast<PngErrorSink*>(png_get_error_ptr(png));
  std::snprintf(sink->message, sizeof sink->message, "%s", msg ? msg : "unknown libpng error");
  png_longjmp(png, 1);
}

extern "C" void png_ignore_warning(png_structp, png_const_charp) {}

// ---- reading ----

struct PngReader {
  std::optional<InputFile> file;
  png_structp png = nullptr;
  png_infop info = nullptr;
  PngErrorSink errors;
  bool ended_early = false;  // the file ended before libpng had what it needed
  char read_error[256] = {0};

  ~PngReader() {
    if (png) png_destroy_read_struct(&png, info ? &info : nullptr, nullptr);
  }
};

// libpng's read callback over the checked, bounded InputFile. An exception
// must not cross libpng's C frames: the message is kept and png_error
// (a longjmp) is called outside the catch block.
extern "C" void png_read_from_input_file(png_structp png, png_bytep data, png_size_t n) {
  auto* r = static_cast<PngReader*>(png_get_io_ptr(png));
  std::size_t got = 0;
  bool failed = false;
  try {
    got = r->file->read(data, n);
  } catch (const std::exception& e) {
    std::snprintf(r->read_error, sizeof r->read_error, "%s", e.what());
    failed = true;
  }
  if (failed) png_error(png, r->read_error);
  if (got < n) {
    r->ended_early = true;
    png_error(png, "Read Error");
  }
}

struct PngLayout {
  png_uint_32 width = 0;
  png_uint_32 height = 0;
  int bit_depth = 0;
  int color_type = 0;
  std::size_t row_bytes = 0;  // after the transformations
};

enum class Transform { kGreyAs8Or16, kRgb8 };

// Reads the header and sets up transformations; false on a libpng error.
bool read_png_header(PngReader* r, Transform transform, PngLayout* out) {
  if (setjmp(png_jmpbuf(r->png))) return false;
  png_set_read_fn(r->png, r, png_read_from_input_file);
  png_set_sig_bytes(r->png, 8);
  png_read_info(r->png, r->info);
  out->width = png_get_image_width(r->png, r->info);
  out->height = png_get_image_height(r->png, r->info);
  out->bit_depth = png_get_bit_depth(r->png, r->info);
  out->color_type = png_get_color_type(r->png, r->info);
  if (transform == Transform::kGreyAs8Or16) {
    if (out->color_type == PNG_COLOR_TYPE_GRAY && out->bit_depth < 8) png_set_expand_gray_1_2_4_to_8(r->png);
  } else {
    if (out->color_type == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(r->png);
    if (out->color_type == PNG_COLOR_TYPE_GRAY && out->bit_depth < 8) png_set_expand_gray_1_2_4_to_8(r->png);
    if (out->color_type == PNG_COLOR_TYPE_GRAY || out->color_type == PNG_COLOR_TYPE_GRAY_ALPHA) {
      png_set_gray_to_rgb(r->png);
    }
    if (out->color_type & PNG_COLOR_MASK_ALPHA) png_set_strip_alpha(r->png);
    if (out->bit_depth == 16) png_set_strip_16(r->png);
  }
  png_set_interlace_handling(r->png);
  png_read_update_info(r->png, r->info);
  out->row_bytes = png_get_rowbytes(r->png, r->info);
  return true;
}

bool read_png_rows(PngReader* r, png_bytepp rows) {
  if (setjmp(png_jmpbuf(r->png))) return false;
  png_read_image(r->png, rows);
  png_read_end(r->png, nullptr);
  return true;
}

const char* colour_type_name(int t) {
  switch (t) {
    case PNG_COLOR_TYPE_GRAY: return "grey";
    case PNG_COLOR_TYPE_GRAY_ALPHA: return "grey+alpha";
    case PNG_COLOR_TYPE_RGB: return "RGB";
    case PNG_COLOR_TYPE_RGB_ALPHA: return "RGBA";
    case PNG_COLOR_TYPE_PALETTE: return "palette";
    default: return "unknown";
  }
}

// Opens the file, checks the signature and creates libpng's structs.
void open_png(const std::string& path, PngReader& r) {
  r.file.emplace(InputFile::open(path, input_kind::kPng));
  png_byte signature[8];
  if (r.file->read(signature, 8) != 8 || png_sig_cmp(signature, 0, 8) != 0) {
    throw InputError(fmt::format("{}: not a PNG file (bad signature)", path));
  }
  r.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &r.errors, png_error_to_sink, png_ignore_warning);
  REPOSE_DEMAND(r.png != nullptr);
  r.info = png_create_info_struct(r.png);
  REPOSE_DEMAND(r.info != nullptr);
}

// libpng says only "Read Error" when the file ends early.
std::string read_failure(const std::string& path, const PngReader& r) {
  if (r.read_error[0] != '\0') return r.read_error;  // already "PATH: REASON"
  if (r.ended_early) return fmt::format("{}: truncated PNG: the file ends early ({})", path, r.errors.message);
  return fmt::format("{}: bad PNG: {}", path, r.errors.message);
}

// The size the header declares, refused when it is not `expected` (a height
// map for a known grid) or too large: before a pixel is decoded.
void check_declared_size(const std::string& path, const PngLayout& layout, const std::optional<PngSize>& expected) {
  if (expected && (layout.width != expected->width || layout.height != expected->height)) {
    throw InputError(fmt::format("{}: its header declares {} x {} pixels (width x height); expected {} x {}", path,
                                 layout.width, layout.height, expected->width, expected->height));
  }
  if (static_cast<std::uint64_t>(layout.width) * layout.height > kMaxPixels) {
    throw InputError(fmt::format("{}: PNG of {} x {} pixels is too large (more than {} pixels)", path, layout.width,
                                 layout.height, kMaxPixels));
  }
}

// Reads the whole image (after `transform`) as rows of bytes, top row first.
std::vector<png_byte> read_png_bytes(const std::string& path, Transform transform, PngLayout& layout,
                                     const char* wanted, const std::optional<PngSize>& expected) {
  PngReader r;
  open_png(path, r);
  if (!read_png_header(&r, transform, &layout)) throw InputError(read_failure(path, r));
  if (transform == Transform::kGreyAs8Or16 && layout.color_type != PNG_COLOR_TYPE_GRAY) {
    throw InputError(fmt::format("{}: PNG colour type is {} ({}-bit); expected {}", path,
                                 colour_type_name(layout.color_type), layout.bit_depth, wanted));
  }
  check_declared_size(path, layout, expected);
  // the decoded rows, and the array of doubles a height map becomes
  require_memory(memory_estimate::sum(memory_estimate::product(layout.row_bytes, layout.height),
                                      memory_estimate::image_bytes(layout.width, layout.height, sizeof(double))),
                 fmt::format("{}: a PNG of {} x {} pixels", path, layout.width, layout.height));
  std::vector<png_byte> pixels(layout.row_bytes * layout.height);
  std::vector<png_bytep> rows(layout.height);
  for (png_uint_32 y = 0; y < layout.height; ++y) rows[y] = pixels.data() + y * layout.row_bytes;
  if (!read_png_rows(&r, rows.data())) throw InputError(read_failure(path, r));
  return pixels;
}

// ---- writing ----

struct PngWriter {
  std::FILE* file = nullptr;
  png_structp png = nullptr;
  png_infop info = nullptr;
  PngErrorSink errors;

  ~PngWriter() {
    if (png) png_destroy_write_struct(&png, info ? &info : nullptr);
    if (file) std::fclose(file);
  }
};

bool write_png_rows(PngWriter* w, png_uint_32 width, png_uint_32 height, int bit_depth, int colour_type,
                    png_bytepp rows) {
  if (setjmp(png_jmpbuf(w->png))) return false;
  png_init_io(w->png, w->file);
  png_set_IHDR(w->png, w->info, width, height, bit_depth, colour_type, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(w->png, w->info);
  png_write_image(w->png, rows);
  png_write_end(w->png, nullptr);
  return true;
}

void write_png_bytes(const std::string& path, int width, int height, int bit_depth, int colour_type,
                     std::vector<png_byte>& pixels) {
  REPOSE_DEMAND(width > 0 && height > 0);
  const std::size_t row_bytes = pixels.size() / static_cast<std::size_t>(height);
  std::vector<png_bytep> rows(static_cast<std::size_t>(height));
  for (int y = 0; y < height; ++y) rows[y] = pixels.data() + static_cast<std::size_t>(y) * row_bytes;
  PngWriter w;
  w.file = std::fopen(path.c_str(), "wb");
  if (!w.file) throw InputError(fmt::format("{}: cannot open for writing: {}", path, std::strerror(errno)));
  w.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &w.errors, png_error_to_sink, png_ignore_warning);
  REPOSE_DEMAND(w.png != nullptr);
  w.info = png_create_info_struct(w.png);
  REPOSE_DEMAND(w.info != nullptr);
  if (!write_png_rows(&w, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), bit_depth, colour_type,
                      rows.data())) {
    throw InputError(fmt::format("{}: cannot write PNG: {}", path, w.errors.message));
  }
  std::FILE* f = w.file;
  w.file = nullptr;
  if (std::fclose(f) != 0) throw InputError(fmt::format("{}: write failed: {}", path, std::strerror(errno)));
}

}  // namespace

PngSize read_png_size(const std::string& path) {
  PngReader r;
  open_png(path, r);
  PngLayout layout;
  if (!read_png_header(&r, Transform::kGreyAs8Or16, &layout)) throw InputError(read_failure(path, r));
  return {layout.width, layout.height};
}

ArrayXXdR read_png16(const std::string& path) { return read_png16(path, std::nullopt); }

ArrayXXdR read_png16(const std::string& path, Eigen::Index rows, Eigen::Index cols) {
  REPOSE_DEMAND(rows >= 0 && cols >= 0 && rows <= 0xffffffffLL && cols <= 0xffffffffLL);
  return read_png16(path, PngSize{static_cast<std::uint32_t>(cols), static_cast<std::uint32_t>(rows)});
}

ArrayXXdR read_png16(const std::string& path, const std::optional<PngSize>& expected) {
  PngLayout layout;
  const std::vector<png_byte> pixels =
      read_png_bytes(path, Transform::kGreyAs8Or16, layout, "16-bit or 8-bit grey", expected);
  const int nx = static_cast<int>(layout.width);
  const int ny = static_cast<int>(layout.height);
  const bool sixteen = layout.bit_depth == 16;
  ArrayXXdR values(ny, nx);
  for (int y = 0; y < ny; ++y) {
    const png_byte* row = pixels.data() + static_cast<std::size_t>(y) * layout.row_bytes;
    for (int x = 0; x < nx; ++x) {
      // PNG samples are big-endian; 8-bit v maps to v * 257 so that 255 -> 65535
      const int v = sixteen ? (row[2 * x] << 8) | row[2 * x + 1] : row[x] * 257;
      values(ny - 1 - y, x) = v;  // top image row = largest y
    }
  }
  return values;
}

void write_png16(const std::string& path, const ArrayXXdR& values) {
  const int ny = static_cast<int>(values.rows());
  const int nx = static_cast<int>(values.cols());
  std::vector<png_byte> pixels(static_cast<std::size_t>(nx) * ny * 2);
  for (int y = 0; y < ny; ++y) {
    for (int x = 0; x < nx; ++x) {
      const double v = values(ny - 1 - y, x);
      if (std::isnan(v)) {
        throw InputError(fmt::format("{}: cannot write NaN (row {}, column {}) to a 16-bit PNG", path, ny - 1 - y, x));
      }
      const auto q = static_cast<unsigned>(std::lround(std::clamp(v, 0.0, 65535.0)));
      const std::size_t k = (static_cast<std::size_t>(y) * nx + x) * 2;
      pixels[k] = static_cast<png_byte>(q >> 8);
      pixels[k + 1] = static_cast<png_byte>(q & 0xff);
    }
  }
  write_png_bytes(path, nx, ny, 16, PNG_COLOR_TYPE_GRAY, pixels);
}

void write_png_rgb(const std::string& path, const RgbImage& image) {
  REPOSE_DEMAND(image.rgb.size() == static_cast<std::size_t>(image.width) * image.height * 3);
  std::vector<png_byte> pixels(image.rgb.begin(), image.rgb.end());
  write_png_bytes(path, image.width, image.height, 8, PNG_COLOR_TYPE_RGB, pixels);
}

RgbImage read_png_rgb(const std::string& path) {
  PngLayout layout;
  std::vector<png_byte> pixels = read_png_bytes(path, Transform::kRgb8, layout, "RGB", std::nullopt);
  REPOSE_DEMAND(layout.row_bytes == static_cast<std::size_t>(layout.width) * 3);
  RgbImage image;
  image.width = static_cast<int>(layout.width);
  image.height = static_cast<int>(layout.height);
  image.rgb.assign(pixels.begin(), pixels.end());
  return image;
}

}  // namespace repose
