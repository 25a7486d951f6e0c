#include "experiments/tearing/tear_render.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/tearing/tear_path.h"

namespace repose {

void TearRenderOptions::validate() const {
  const auto require = [](bool ok, const char* field, double value, const char* rule) {
    if (!ok) throw InputError(fmt::format("tearing render: {} = {} must be {}", field, value, rule));
  };
  require(width_px >= 1 && width_px <= 8192, "width_px", width_px, "in [1, 8192]");
  require(height_px >= 1 && height_px <= 8192, "height_px", height_px, "in [1, 8192]");
  require(std::abs(azimuth_deg) < 90.0, "azimuth_deg", azimuth_deg, "in (-90, 90)");
  require(std::abs(elevation_deg) < 90.0, "elevation_deg", elevation_deg, "in (-90, 90)");
  require(fov_y_deg > 0.0 && fov_y_deg < 120.0, "fov_y_deg", fov_y_deg, "in (0, 120)");
  require(layer_spacing_m >= 0.0 && layer_spacing_m < 1e-3, "layer_spacing_m", layer_spacing_m, "in [0, 1e-3)");
  require(supersample >= 1 && supersample <= 4, "supersample", supersample, "in [1, 4]");
  require(std::isfinite(close_up_m) && close_up_m >= 0.0, "close_up_m", close_up_m, ">= 0");
}

namespace {

constexpr double kRad = std::numbers::pi / 180.0;

// Colour of fibre layer k at density d in [0, 1]: the top layer green, the
// others white, darker where denser.
Eigen::Vector3d layer_rgb(std::size_t k, double d) {
  d = std::clamp(d, 0.0, 1.0);
  const Eigen::Vector3d light = k == 0 ? Eigen::Vector3d(0.66, 0.88, 0.60) : Eigen::Vector3d(0.99, 0.99, 0.97);
  const Eigen::Vector3d dense = k == 0 ? Eigen::Vector3d(0.20, 0.56, 0.24) : Eigen::Vector3d(0.80, 0.80, 0.76);
  return (1.0 - d) * light + d * dense;
}

double density_at(const ArrayXXdR& layer, double pixel_m, double x, double y) {
  const int c = std::clamp(static_cast<int>(x / pixel_m), 0, static_cast<int>(layer.cols()) - 1);
  const int r = std::clamp(static_cast<int>(y / pixel_m), 0, static_cast<int>(layer.rows()) - 1);
  return layer(r, c);
}

// The deformed position of rest point (x, y) inside cell (i, j), bilinear in its corners.
Eigen::Vector3d bilinear(const SheetModel& m, const SheetState& s, int i, int j, double u, double v) {
  const auto p = [&](int a, int b) -> Eigen::Vector3d { return s.positions.col(m.vertex(a, b)); };
  return (1 - v) * ((1 - u) * p(i, j) + u * p(i + 1, j)) + v * ((1 - u) * p(i, j + 1) + u * p(i + 1, j + 1));
}

// The intact cells on a grid `sub` times finer than the mesh, so that the
// fibre density shades the sheet at about the image's resolution.
ColouredMesh intact_mesh(const SheetModel& m, const SheetState& s, const FibreImages& images) {
  const double h = m.cell_size_m;
  const int sub = std::clamp(static_cast<int>(std::lround(h / images.pixel_size_m)), 1, 8);
  const int nx = m.cells_x * sub + 1, ny = m.cells_y * sub + 1;
  ColouredMesh out;
  out.mesh.V.resize(static_cast<Eigen::Index>(nx) * ny, 3);
  out.vertex_rgb.resize(static_cast<std::size_t>(nx) * ny);
  for (int b = 0; b < ny; ++b) {
    for (int a = 0; a < nx; ++a) {
      const int i = std::min(a / sub, m.cells_x - 1), j = std::min(b / sub, m.cells_y - 1);
      const double u = static_cast<double>(a - i * sub) / sub, v = static_cast<double>(b - j * sub) / sub;
      const Eigen::Index row = static_cast<Eigen::Index>(b) * nx + a;
      out.mesh.V.row(row) = bilinear(m, s, i, j, u, v).transpose();
      out.vertex_rgb[static_cast<std::size_t>(row)] =
          layer_rgb(0, density_at(images.layers[0], images.pixel_size_m, (i + u) * h, (j + v) * h));
    }
  }
  std::vector<int> faces;
  for (int j = 0; j < m.cells_y; ++j) {
    for (int i = 0; i < m.cells_x; ++i) {
      if (!s.intact(m.cell(i, j))) continue;
      for (int q = 0; q < sub; ++q) {
        for (int p = 0; p < sub; ++p) {
          const int v00 = (j * sub + q) * nx + i * sub + p, v10 = v00 + 1, v01 = v00 + nx, v11 = v01 + 1;
          faces.insert(faces.end(), {v00, v10, v11, v00, v11, v01});
        }
      }
    }
  }
  out.mesh.F = Eigen::Map<const MatrixX3iR>(faces.data(), static_cast<Eigen::Index>(faces.size() / 3), 3);
  return out;
}

// One torn cell's row of the layered edge: where its pieces hang.
struct TornRow {
  const SheetModel* m;
  const SheetState* s;
  int i, j;  // the torn cell

  Eigen::Vector3d column_at(int col, double y) const {
    const double v = std::clamp(y / m->cell_size_m - j, 0.0, 1.0);
    return (1 - v) * s->positions.col(m->vertex(col, j)) + v * s->positions.col(m->vertex(col, j + 1));
  }
  // The piece's x axis: along the intact neighbour's row, or the rest x axis.
  Eigen::Vector3d axis(bool left, double y) const {
    const int nb = left ? i - 1 : i + 1;
    if (nb < 0 || nb >= m->cells_x || !s->intact(m->cell(nb, j))) return Eigen::Vector3d::UnitX();
    const Eigen::Vector3d d = left ? column_at(i, y) - column_at(i - 1, y) : column_at(i + 2, y) - column_at(i + 1, y);
    return d / m->cell_size_m;
  }
  // Whether the piece's vertex column, and its intact neighbour's, are whole
  // here (not pulled apart by a tear turning sideways).
  bool holds(bool left) const {
    const auto edge = [&](int col) {
      return (s->positions.col(m->vertex(col, j + 1)) - s->positions.col(m->vertex(col, j))).norm();
    };
    const int col = left ? i : i + 1, nb = left ? i - 1 : i + 2;
    const double most = 1.5 * m->cell_size_m;
    return edge(col) < most && (nb < 0 || nb > m->cells_x || edge(nb) < most) && axis(left, j * m->cell_size_m).norm() < 1.5;
  }
  // Rest point (x, y) carried by the left or right piece, `behind` metres
  // behind its top face.
  Eigen::Vector3d place(bool left, double x, double y, double behind) const {
    const int col = left ? i : i + 1;
    const Eigen::Vector3d e = axis(left, y);
    const Eigen::Vector3d t = s->positions.col(m->vertex(col, j + 1)) - s->positions.col(m->vertex(col, j));
    Eigen::Vector3d n = e.cross(t);
    n = n.squaredNorm() > 0.0 ? n.normalized() : Eigen::Vector3d::UnitZ();
    return column_at(col, y) + (x - col * m->cell_size_m) * e - behind * n;
  }
};

// The torn cell of mesh row j nearest x, or -1.
int torn_cell_near(const SheetModel& m, const SheetState& s, int j, double x) {
  int best = -1;
  double distance = 0.0;
  for (int i = 0; i < m.cells_x; ++i) {
    if (s.intact(m.cell(i, j))) continue;
    const double d = std::abs((i + 0.5) * m.cell_size_m - x);
    if (best < 0 || d < distance) best = i, distance = d;
  }
  return best;
}

// A strip [x0, x1] x [y0, y1] of layer k on one piece, split at the image's pixels.
void add_strip(const TornRow& row, bool left, double x0, double x1, double y0, double y1, std::size_t k,
               double behind, const FibreImages& images, std::vector<Eigen::Vector3d>* v,
               std::vector<Eigen::Vector3d>* rgb, std::vector<int>* faces) {
  if (!(x1 > x0)) return;
  const int pieces = std::max(1, static_cast<int>(std::ceil((x1 - x0) / images.pixel_size_m - 1e-9)));
  const int base = static_cast<int>(v->size());
  for (int p = 0; p <= pieces; ++p) {
    const double x = x0 + (x1 - x0) * p / pieces;
    for (const double y : {y0, y1}) {
      v->push_back(row.place(left, x, y, behind));
      rgb->push_back(layer_rgb(k, density_at(images.layers[k], images.pixel_size_m, x, 0.5 * (y0 + y1))));
    }
  }
  for (int p = 0; p < pieces; ++p) {
    const int a = base + 2 * p, b = a + 2;  // a: (x_p, y0), a + 1: (x_p, y1)
    faces->insert(faces->end(), {a, b, b + 1, a, b + 1, a + 1});
  }
}

ColouredMesh layer_mesh(const SheetModel& m, const SheetState& s, const FibreImages& images, const LayerCuts& cuts,
                        std::size_t k, double behind) {
  std::vector<Eigen::Vector3d> v, rgb;
  std::vector<int> faces;
  const double px = images.pixel_size_m, h = m.cell_size_m;
  for (int r = 0; r < images.ny(); ++r) {
    const double top_cut = cuts.cut_x_m[0][static_cast<std::size_t>(r)], cut = cuts.cut_x_m[k][static_cast<std::size_t>(r)];
    if (std::isnan(top_cut) || std::isnan(cut)) continue;
    const double y0 = r * px, y1 = std::min((r + 1) * px, m.cells_y * h);
    const int j = std::clamp(static_cast<int>((y0 + 0.5 * px) / h), 0, m.cells_y - 1);
    const int i = torn_cell_near(m, s, j, top_cut);
    if (i < 0 || !(y1 > y0)) continue;
    const TornRow row{&m, &s, i, j};
    const double xa = i * h, xb = (i + 1) * h, c = std::clamp(cut, xa, xb);
    if (row.holds(true)) add_strip(row, true, xa, c, y0, y1, k, behind, images, &v, &rgb, &faces);
    if (row.holds(false)) add_strip(row, false, c, xb, y0, y1, k, behind, images, &v, &rgb, &faces);
  }
  ColouredMesh out;
  out.mesh.V.resize(static_cast<Eigen::Index>(v.size()), 3);
  for (std::size_t q = 0; q < v.size(); ++q) out.mesh.V.row(static_cast<Eigen::Index>(q)) = v[q].transpose();
  out.mesh.F = Eigen::Map<const MatrixX3iR>(faces.data(), static_cast<Eigen::Index>(faces.size() / 3), 3);
  out.vertex_rgb = std::move(rgb);
  return out;
}

}  // namespace

CameraSpec tear_camera(const SheetModel& model, const SheetState& state, const TearRenderOptions& options) {
  options.validate();
  REPOSE_DEMAND(state.positions.cols() == model.vertex_count() && state.positions.allFinite());
  const Eigen::Vector3d lo = state.positions.rowwise().minCoeff(), hi = state.positions.rowwise().maxCoeff();
  CameraSpec c;
  c.width_px = options.width_px;
  c.height_px = options.height_px;
  c.fov_y_rad = options.fov_y_deg * kRad;
  c.target_m = 0.5 * (lo + hi);
  double radius = std::max(0.5 * (hi - lo).norm(), 1e-3);
  const TearPath path = options.close_up_m > 0.0 ? measure_tear_path(model, state) : TearPath{};
  if (!path.points.empty()) {  // the tip: the deformed middle of the path's last cell
    const Eigen::Vector2d tip = path.points.back();
    const double h = model.cell_size_m;
    const int i = std::clamp(static_cast<int>(tip.x() / h), 0, model.cells_x - 1);
    const int j = std::clamp(static_cast<int>(tip.y() / h), 0, model.cells_y - 1);
    c.target_m = bilinear(model, state, i, j, 0.5, 0.5);
    radius = options.close_up_m;
  }
  const double aspect = static_cast<double>(c.width_px) / c.height_px;
  const double half = std::min(c.fov_y_rad / 2, std::atan(std::tan(c.fov_y_rad / 2) * aspect));
  const double az = options.azimuth_deg * kRad, el = options.elevation_deg * kRad;
  const Eigen::Vector3d towards_eye(std::sin(az) * std::cos(el), std::sin(el), std::cos(az) * std::cos(el));
  c.position_m = c.target_m + 1.05 * radius / std::sin(half) * towards_eye;
  c.up = Eigen::Vector3d::UnitY();
  return c;
}

std::vector<ColouredMesh> tear_meshes(const SheetModel& model, const SheetState& state, const FibreImages& images,
                                      const LayerCuts& cuts, const TearRenderOptions& options) {
  options.validate();
  REPOSE_DEMAND(cuts.cut_x_m.size() == images.layers.size());
  std::vector<ColouredMesh> meshes{intact_mesh(model, state, images)};
  for (std::size_t k = 0; k < images.layers.size(); ++k) {
    meshes.push_back(layer_mesh(model, state, images, cuts, k, static_cast<double>(k) * options.layer_spacing_m));
  }
  return meshes;
}

RgbImage render_tear(const SheetModel& model, const SheetState& state, const FibreImages& images,
                     const TearEdgeOptions& edge, const TearRenderOptions& options) {
  options.validate();
  const LayerCuts cuts = trace_layer_cuts(model, state, images, edge);
  RenderImageOptions look;
  look.supersample = options.supersample;
  look.light_direction = Eigen::Vector3d(-0.35, 0.45, 1.0);  // from the viewer's upper left
  look.ambient = 0.4;
  look.background_rgb = Eigen::Vector3d(0.13, 0.13, 0.17);
  return render_coloured_meshes(tear_meshes(model, state, images, cuts, options), tear_camera(model, state, options),
                                look);
}

}  // namespace repose
