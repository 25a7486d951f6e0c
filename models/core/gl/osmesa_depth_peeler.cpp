#include "models/core/gl/osmesa_depth_peeler.h"

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/core/gl/osmesa_depth_renderer.h"

namespace repose {

namespace {

// Fixed-function vertices; the fragment is kept only beyond the layer below.
const char* const kPeelShader = R"(#version 120
uniform sampler2D previous_depth;
uniform vec2 window_px;
uniform float margin;
void main() {
  if (gl_FragCoord.z <= texture2D(previous_depth, gl_FragCoord.xy / window_px).r + margin) discard;
  gl_FragColor = vec4(1.0);
}
)";

unsigned compile_program() {
  const GLuint shader = glCreateShader(GL_FRAGMENT_SHADER);
  glShaderSource(shader, 1, &kPeelShader, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[1024] = {0};
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    throw std::runtime_error(std::string("depth peeling shader: ") + log);
  }
  const GLuint program = glCreateProgram();
  glAttachShader(program, shader);
  glLinkProgram(program);
  glDeleteShader(shader);
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) throw std::runtime_error("depth peeling shader: the program does not link");
  return program;
}

}  // namespace

OsmesaDepthPeeler::OsmesaDepthPeeler() : context_(1, 1) {
  program_ = compile_program();
  GLuint texture = 0;
  glGenTextures(1, &texture);
  texture_ = texture;
}

OsmesaDepthPeeler::~OsmesaDepthPeeler() {
  context_.make_current(1, 1);
  const GLuint texture = texture_;
  glDeleteTextures(1, &texture);
  glDeleteProgram(program_);
}

DepthLayers OsmesaDepthPeeler::peel_from_below(const TriangleMesh& mesh, const Grid& grid, DepthRange range,
                                               int max_layers) {
  if (grid.nx < 1 || grid.ny < 1 || grid.nx > context_.max_size_px() || grid.ny > context_.max_size_px()) {
    throw InputError(fmt::format("depth peeling: a grid of {} x {} cells, at most {} a side", grid.nx, grid.ny,
                                 context_.max_size_px()));
  }
  DepthLayers layers;
  layers.grid = grid;
  layers.z_m.resize(grid.cell_count());
  if (mesh.empty()) return layers;
  context_.make_current(grid.nx, grid.ny);
  const std::vector<float> ndc = depth_device_coordinates(mesh, grid, 0, 0, grid.nx, grid.ny, ViewFrom::kBelow, range);
  const std::size_t pixels = grid.cell_count();
  std::vector<float> previous(pixels, -1.0f), depth(pixels);
  glUseProgram(program_);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, texture_);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glUniform1i(glGetUniformLocation(program_, "previous_depth"), 0);
  glUniform2f(glGetUniformLocation(program_, "window_px"), static_cast<float>(grid.nx), static_cast<float>(grid.ny));
  glUniform1f(glGetUniformLocation(program_, "margin"), static_cast<float>(2.0 / (std::ldexp(1.0, context_.depth_bits()) - 1.0)));
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  for (int pass = 0;; ++pass) {
    set_depth_only_gl_state();
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, grid.nx, grid.ny, 0, GL_RED, GL_FLOAT, previous.data());
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, ndc.data());
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(mesh.F.size()), GL_UNSIGNED_INT, mesh.F.data());
    glDisableClientState(GL_VERTEX_ARRAY);
    glReadPixels(0, 0, grid.nx, grid.ny, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
    bool any = false;
    for (std::size_t k = 0; k < pixels; ++k) {
      if (!(depth[k] < 1.0f)) {
        previous[k] = 2.0f;  // nothing more here
        continue;
      }
      any = true;
      if (pass >= max_layers) {
        throw InputError(fmt::format("depth peeling: more than {} surfaces over one cell", max_layers));
      }
      layers.z_m[k].push_back(range.z_min_m + depth[k] * (range.z_max_m - range.z_min_m));
      previous[k] = depth[k];
    }
    if (!any) break;
  }
  glUseProgram(0);
  return layers;
}

}  // namespace repose
