#include "models/core/gl/osmesa_context.h"

#include <GL/osmesa.h>

#include <GL/gl.h>

#include <algorithm>
#include <stdexcept>
#include <string>

#include "models/core/base/error.h"

namespace repose {

namespace {

constexpr int kDepthBits = 24;  // OSMesa's maximum (32 is silently reduced to 24)
constexpr int kStencilBits = 8;

}  // namespace

OsmesaContext::OsmesaContext(int width_px, int height_px) : owner_(std::this_thread::get_id()) {
  const int attributes[] = {OSMESA_FORMAT,       OSMESA_RGBA, OSMESA_DEPTH_BITS, kDepthBits,
                            OSMESA_STENCIL_BITS, kStencilBits, OSMESA_ACCUM_BITS, 0,
                            OSMESA_PROFILE,      OSMESA_COMPAT_PROFILE, 0};
  context_ = OSMesaCreateContextAttribs(attributes, nullptr);
  if (context_ == nullptr) {
    throw std::runtime_error(
        "OSMesa: cannot create an off-screen OpenGL context (RGBA, 24-bit depth, 8-bit stencil); "
        "is libosmesa6 installed?");
  }
  try {
    // a 1x1 binding first, to query the limits before the requested size
    make_current(1, 1);
    const GLubyte* renderer = glGetString(GL_RENDERER);
    if (renderer == nullptr) {
      throw std::runtime_error(
          "OSMesa: glGetString(GL_RENDERER) is NULL: the program links libGL before libOSMesa; "
          "link OSMesa alone (pkg-config osmesa)");
    }
    renderer_ = reinterpret_cast<const char*>(renderer);
    GLint viewport_max[2] = {0, 0};
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport_max);
    GLint osmesa_max_w = 0, osmesa_max_h = 0;
    OSMesaGetIntegerv(OSMESA_MAX_WIDTH, &osmesa_max_w);
    OSMesaGetIntegerv(OSMESA_MAX_HEIGHT, &osmesa_max_h);
    max_size_px_ = std::min({viewport_max[0], viewport_max[1], osmesa_max_w, osmesa_max_h});
    glGetIntegerv(GL_DEPTH_BITS, &depth_bits_);
    glGetIntegerv(GL_STENCIL_BITS, &stencil_bits_);
    if (max_size_px_ < 1 || depth_bits_ < 24) {
      throw std::runtime_error("OSMesa: the context has a " + std::to_string(depth_bits_) +
                               "-bit depth buffer and maximum size " + std::to_string(max_size_px_) +
                               " px; repose needs at least 24 bits");
    }
    make_current(width_px, height_px);
  } catch (...) {
    OSMesaDestroyContext(context_);
    throw;
  }
}

OsmesaContext::~OsmesaContext() {
  if (OSMesaGetCurrentContext() == context_) OSMesaMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
  OSMesaDestroyContext(context_);
}

void OsmesaContext::make_current(int width_px, int height_px) {
  REPOSE_DEMAND(std::this_thread::get_id() == owner_);  // one context per thread
  REPOSE_DEMAND(width_px >= 1 && height_px >= 1);
  REPOSE_DEMAND(max_size_px_ == 0 || (width_px <= max_size_px_ && height_px <= max_size_px_));
  const bool resized = width_px != width_px_ || height_px != height_px_;
  if (resized) {
    rgba_.assign(static_cast<std::size_t>(width_px) * static_cast<std::size_t>(height_px) * 4, 0);
    width_px_ = width_px;
    height_px_ = height_px;
  }
  if (!OSMesaMakeCurrent(context_, rgba_.data(), GL_UNSIGNED_BYTE, width_px_, height_px_)) {
    throw std::runtime_error("OSMesa: cannot make the context current with a " + std::to_string(width_px_) + "x" +
                             std::to_string(height_px_) + " buffer");
  }
  if (resized) glViewport(0, 0, width_px_, height_px_);
}

}  // namespace repose
