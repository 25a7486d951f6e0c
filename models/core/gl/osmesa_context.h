#pragma once
// An off-screen OpenGL context: OSMesa (Mesa's llvmpipe software rasteriser,
// GL 4.5 compatibility profile) drawing into a buffer in main memory, so
// depth images and figures render without a display or a GPU.
//
// Buffers: RGBA 8 bits per channel, a 24-bit depth buffer and an 8-bit
// stencil buffer. Mesa 22.3's OSMesa gives at most 24 depth bits (asking for
// 32 returns 24), so a depth image over a z range R resolves R / (2^24 - 1).
//
// One context per thread: OpenGL binds a context to the thread that makes it
// current, so a context is used only on the thread that created it (checked).
// Several contexts may live on one thread; make_current() before drawing.
//
// Link OSMesa alone (pkg-config osmesa): with libGL linked first,
// glGetString returns NULL and nothing renders; the constructor detects that.

#include <cstdint>
#include <string>
#include <thread>
#include <vector>

struct osmesa_context;  // OSMesaContext, kept out of this header with <GL/osmesa.h>

namespace repose {

class OsmesaContext {
 public:
  // Creates the context and makes it current with a width x height buffer.
  // Throws std::runtime_error when OSMesa cannot create or bind a context.
  OsmesaContext(int width_px, int height_px);
  ~OsmesaContext();
  OsmesaContext(const OsmesaContext&) = delete;
  OsmesaContext& operator=(const OsmesaContext&) = delete;

  // Makes this context current on the calling thread, with a colour buffer of
  // width x height pixels (reallocated when the size changes; the viewport is
  // reset to the whole buffer). Sizes are 1..max_size_px().
  void make_current(int width_px, int height_px);

  int width_px() const { return width_px_; }
  int height_px() const { return height_px_; }
  // The colour buffer: width * height * 4 bytes RGBA, row 0 at the bottom.
  const std::vector<std::uint8_t>& rgba() const { return rgba_; }

  int depth_bits() const { return depth_bits_; }
  int stencil_bits() const { return stencil_bits_; }
  // Largest buffer and viewport side (GL_MAX_VIEWPORT_DIMS and OSMESA_MAX_WIDTH/HEIGHT).
  int max_size_px() const { return max_size_px_; }
  std::string renderer() const { return renderer_; }

 private:
  osmesa_context* context_ = nullptr;
  std::thread::id owner_;
  int width_px_ = 0;
  int height_px_ = 0;
  std::vector<std::uint8_t> rgba_;
  int depth_bits_ = 0;
  int stencil_bits_ = 0;
  int max_size_px_ = 0;
  std::string renderer_;
};

}  // namespace repose
