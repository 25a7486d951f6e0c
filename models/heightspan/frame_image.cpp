#include "models/heightspan/frame_image.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "models/core/base/error.h"
#include "models/heightspan/heightspan_model.h"
#include "models/heightspan/heightspan_state.h"

namespace repose {

namespace {

using Rgb = std::array<double, 3>;
constexpr Rgb kGroundRgb{0.72, 0.58, 0.38}, kObjectRgb{0.45, 0.47, 0.50}, kMaterialRgb{0.96, 0.82, 0.52},
    kParticleRgb{0.35, 0.22, 0.10}, kBackgroundRgb{1.0, 1.0, 1.0};

enum class Top { kGround, kObject, kMaterial };

void put(RgbImage* img, int x, int y, const Rgb& c, double shade = 1.0) {
  if (x < 0 || y < 0 || x >= img->width || y >= img->height) return;
  for (int k = 0; k < 3; ++k) {
    const double v = std::clamp(c[k] * shade, 0.0, 1.0);
    img->rgb[(static_cast<std::size_t>(y) * img->width + x) * 3 + k] = static_cast<std::uint8_t>(std::lround(255 * v));
  }
}

// What lies at (x, z) in the held objects' maps: 0 nothing, 1 solid, 2 material.
int held_at(const HeightSpanState& state, double x, double y, double z) {
  for (const ObjectSpans& h : state.held) {
    int i, j;
    if (!h.map.cell_at(x, y, &i, &j)) continue;
    const std::int64_t c = h.map.cell(i, j);
    const Span* s = h.map.begin(c);
    for (int k = 0; k < h.map.count(c); ++k) {
      if (z >= s[k].bottom_m && z <= s[k].top_m) return 1;
      if (z > s[k].top_m && z <= s[k].level_m()) return 2;
    }
  }
  return 0;
}

void draw_section(const HeightSpanModel& model, const HeightSpanState& state, const FrameView& v, int rows,
                  RgbImage* img) {
  const Grid& g = model.ground.grid;
  const double dz = (v.z_max_m - v.z_min_m) / rows;
  const int j = std::clamp(static_cast<int>(std::floor((v.section_y_m - g.origin_y_m) / g.cell_size_m)), 0, g.ny - 1);
  for (int x = 0; x < img->width; ++x) {
    const double wx = g.origin_x_m + (x + 0.5) * g.cell_size_m / v.px_per_cell;
    const int i = std::min(g.nx - 1, x / v.px_per_cell);
    for (int r = 0; r < rows; ++r) {
      const double z = v.z_max_m - (r + 0.5) * dz;
      const int held = held_at(state, wx, v.section_y_m, z);
      const Rgb& c = held == 1                                ? kObjectRgb
                     : held == 2                              ? kMaterialRgb
                     : z <= state.ground.height.at(i, j)      ? kGroundRgb
                                                              : kBackgroundRgb;
      put(img, x, r, c);
    }
  }
  for (const Particle& p : state.particles.particles) {
    if (std::abs(p.position_m.y() - v.section_y_m) > 2 * g.cell_size_m) continue;
    const int x = static_cast<int>(std::floor((p.position_m.x() - g.origin_x_m) / g.cell_size_m * v.px_per_cell));
    const int r = static_cast<int>(std::floor((v.z_max_m - p.position_m.z()) / dz));
    for (int d = 0; d < 4; ++d) put(img, x + d % 2, r + d / 2, kParticleRgb);
  }
}

void draw_plan(const HeightSpanModel& model, const HeightSpanState& state, const FrameView& v, int row0,
               RgbImage* img) {
  const Grid& g = model.ground.grid;
  ArrayXXdR top = state.ground.height.heights();
  std::vector<Top> kind(g.cell_count(), Top::kGround);
  for (const ObjectSpans& h : state.held) {
    for (int j = 0; j < g.ny; ++j) {
      for (int i = 0; i < g.nx; ++i) {
        int mi, mj;
        if (!h.map.cell_at(g.centre_x(i), g.centre_y(j), &mi, &mj)) continue;
        const std::int64_t c = h.map.cell(mi, mj);
        if (h.map.count(c) == 0) continue;
        const Span& s = h.map.begin(c)[h.map.count(c) - 1];
        if (s.level_m() <= top(j, i)) continue;
        top(j, i) = s.level_m();
        kind[static_cast<std::size_t>(j) * g.nx + i] = s.material_m > 1e-6 * g.cell_size_m ? Top::kMaterial : Top::kObject;
      }
    }
  }
  const Eigen::Vector3d light = Eigen::Vector3d(-0.5, 0.3, 1.0).normalized();
  for (int j = 0; j < g.ny; ++j) {
    for (int i = 0; i < g.nx; ++i) {
      const double sx = (top(j, std::min(i + 1, g.nx - 1)) - top(j, std::max(i - 1, 0))) / (2 * g.cell_size_m);
      const double sy = (top(std::min(j + 1, g.ny - 1), i) - top(std::max(j - 1, 0), i)) / (2 * g.cell_size_m);
      const double shade = 0.35 + 0.65 * std::max(0.0, Eigen::Vector3d(-sx, -sy, 1.0).normalized().dot(light));
      const Top t = kind[static_cast<std::size_t>(j) * g.nx + i];
      const Rgb& c = t == Top::kObject ? kObjectRgb : t == Top::kMaterial ? kMaterialRgb : kGroundRgb;
      for (int d = 0; d < v.px_per_cell * v.px_per_cell; ++d) {
        put(img, i * v.px_per_cell + d % v.px_per_cell, row0 + (g.ny - 1 - j) * v.px_per_cell + d / v.px_per_cell, c,
            shade / 0.85);
      }
    }
  }
}

}  // namespace

RgbImage render_frame(const HeightSpanModel& model, const HeightSpanState& state, const FrameView& view) {
  if (view.px_per_cell < 1 || view.px_per_cell > 16 || !(view.z_max_m > view.z_min_m)) {
    throw InputError("render_frame: px_per_cell must be in [1, 16] and z_max_m above z_min_m");
  }
  const Grid& g = model.ground.grid;
  const int rows = std::clamp(static_cast<int>(std::ceil((view.z_max_m - view.z_min_m) / g.cell_size_m)) *
                                  view.px_per_cell, 1, 2000);
  RgbImage img;
  img.width = g.nx * view.px_per_cell;
  img.height = rows + 4 + g.ny * view.px_per_cell;
  img.rgb.assign(static_cast<std::size_t>(img.width) * img.height * 3, 255);
  draw_section(model, state, view, rows, &img);
  draw_plan(model, state, view, rows + 4, &img);
  return img;
}

}  // namespace repose
