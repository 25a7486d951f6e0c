#include "models/tearing/sheet_model.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "models/core/base/error.h"

namespace repose {

namespace {

// Bilinear sample of the image at (x, y) m; pixel centres at (c + 0.5) px.
double sample(const FibreImages& images, double x_m, double y_m) {
  const ArrayXXdR& d = images.composite;
  const double u = std::clamp(x_m / images.pixel_size_m - 0.5, 0.0, static_cast<double>(d.cols() - 1));
  const double v = std::clamp(y_m / images.pixel_size_m - 0.5, 0.0, static_cast<double>(d.rows() - 1));
  const int c0 = std::min(static_cast<int>(u), static_cast<int>(d.cols()) - 1);
  const int r0 = std::min(static_cast<int>(v), static_cast<int>(d.rows()) - 1);
  const int c1 = std::min(c0 + 1, static_cast<int>(d.cols()) - 1), r1 = std::min(r0 + 1, static_cast<int>(d.rows()) - 1);
  const double fu = u - c0, fv = v - r0;
  return (1 - fv) * ((1 - fu) * d(r0, c0) + fu * d(r0, c1)) + fv * ((1 - fu) * d(r1, c0) + fu * d(r1, c1));
}

// Mean density over each cell from n x n samples, n about two per pixel.
Eigen::VectorXd cell_densities(const SheetModel& m, const FibreImages& images) {
  const double h = m.cell_size_m;
  const int n = std::clamp(static_cast<int>(std::ceil(2.0 * h / images.pixel_size_m)), 1, 16);
  Eigen::VectorXd density(m.cell_count());
  for (int j = 0; j < m.cells_y; ++j) {
    for (int i = 0; i < m.cells_x; ++i) {
      double sum = 0.0;
      for (int q = 0; q < n; ++q) {
        for (int p = 0; p < n; ++p) sum += sample(images, (i + (p + 0.5) / n) * h, (j + (q + 0.5) / n) * h);
      }
      density[m.cell(i, j)] = sum / (n * n);
    }
  }
  return density;
}

int cell_or_none(const SheetModel& m, int i, int j) {
  return (i >= 0 && j >= 0 && i < m.cells_x && j < m.cells_y) ? m.cell(i, j) : -1;
}

void add_bending_term(SheetModel* m, int a, int b, int c, std::array<int, 2> ab, std::array<int, 2> bc) {
  BendingTerm t{a, b, c, ab, bc, 0.0};
  int count = 0;
  for (const int cell : {ab[0], ab[1], bc[0], bc[1]}) {
    if (cell < 0) continue;
    t.weight += m->cell_stiffness[cell];
    ++count;
  }
  REPOSE_DEMAND(count > 0);
  t.weight /= count;
  m->bending.push_back(t);
}

void add_bending_terms(SheetModel* m) {
  for (int j = 0; j <= m->cells_y; ++j) {  // along x
    for (int i = 1; i < m->cells_x; ++i) {
      add_bending_term(m, m->vertex(i - 1, j), m->vertex(i, j), m->vertex(i + 1, j),
                       {cell_or_none(*m, i - 1, j - 1), cell_or_none(*m, i - 1, j)},
                       {cell_or_none(*m, i, j - 1), cell_or_none(*m, i, j)});
    }
  }
  for (int i = 0; i <= m->cells_x; ++i) {  // along y
    for (int j = 1; j < m->cells_y; ++j) {
      add_bending_term(m, m->vertex(i, j - 1), m->vertex(i, j), m->vertex(i, j + 1),
                       {cell_or_none(*m, i - 1, j - 1), cell_or_none(*m, i, j - 1)},
                       {cell_or_none(*m, i - 1, j), cell_or_none(*m, i, j)});
    }
  }
}

void attach_grips(SheetModel* m) {
  m->held_axes.assign(m->vertex_count(), 0);
  m->grip_of_vertex.assign(m->vertex_count(), -1);
  for (std::size_t k = 0; k < m->spec.grips.size(); ++k) {
    const GripSpec& g = m->spec.grips[k];
    std::uint8_t bits = 0;
    for (int a = 0; a < 3; ++a) bits |= g.held_axes[a] ? static_cast<std::uint8_t>(1u << a) : 0;
    for (int v = 0; v < m->vertex_count(); ++v) {
      const double x = m->rest_positions(0, v), y = m->rest_positions(1, v);
      const double tol = 1e-9 * (1.0 + std::abs(x) + std::abs(y));
      if (x < g.x_min_m - tol || x > g.x_max_m + tol || y < g.y_min_m - tol || y > g.y_max_m + tol) continue;
      m->grip_of_vertex[v] = static_cast<int>(k);
      m->held_axes[v] = bits;
    }
  }
}

void cut_notch(SheetModel* m) {
  const int rows = static_cast<int>(std::ceil(m->spec.notch_length_m / m->cell_size_m - 1e-9));
  if (rows <= 0) return;
  const int i = std::min(static_cast<int>(m->spec.notch_x_m / m->cell_size_m), m->cells_x - 1);
  for (int j = m->cells_y - 1; j >= m->cells_y - rows; --j) m->notch_cells.push_back(m->cell(i, j));
}

}  // namespace

std::array<int, 4> SheetModel::corners(int cell_index) const {
  const int i = cell_index % cells_x, j = cell_index / cells_x;
  return {vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1), vertex(i, j + 1)};
}

SheetModel build_sheet_model(const SheetSpec& spec, const FibreImages& images) {
  spec.validate();
  SheetModel m;
  m.spec = spec;
  m.cells_x = spec.cells_x;
  m.cells_y = spec.cells_y();
  m.cell_size_m = spec.cell_size_m();
  if (images.composite.size() == 0 || images.nx() * images.pixel_size_m < spec.width_m * (1 - 1e-9) ||
      images.ny() * images.pixel_size_m < spec.height_m * (1 - 1e-9)) {
    throw InputError(fmt::format("tearing sheet: the fibre images ({} x {} pixels of {} m) do not cover the {} x {} m sheet",
                                 images.nx(), images.ny(), images.pixel_size_m, spec.width_m, spec.height_m));
  }
  const int nv = (m.cells_x + 1) * (m.cells_y + 1);
  m.rest_positions = Eigen::Matrix3Xd::Zero(3, nv);
  for (int j = 0; j <= m.cells_y; ++j) {
    for (int i = 0; i <= m.cells_x; ++i) m.rest_positions.col(m.vertex(i, j)) << i * m.cell_size_m, j * m.cell_size_m, 0.0;
  }
  const Eigen::VectorXd density = cell_densities(m, images);
  const double mean = density.mean();
  if (!(mean > 0.0)) throw InputError("tearing sheet: the fibre image is empty (mean density 0) over the sheet");
  m.cell_weight = density / mean;
  m.cell_stiffness = m.cell_weight.array().pow(spec.stiffness_density_exponent).matrix();
  m.cell_tear_factor = m.cell_weight.array().pow(spec.tear_strain_density_exponent).matrix();
  m.mass_kg = Eigen::VectorXd::Zero(nv);
  const double quarter_cell_kg = 0.25 * spec.grammage_kg_per_m2 * m.cell_size_m * m.cell_size_m;
  for (int c = 0; c < m.cell_count(); ++c) {
    for (const int v : m.corners(c)) m.mass_kg[v] += quarter_cell_kg * m.cell_weight[c];
  }
  if (!(m.mass_kg.minCoeff() > 0.0)) {
    throw InputError("tearing sheet: a vertex has no mass (its cells have no fibre): raise fibres.background_density");
  }
  add_bending_terms(&m);
  attach_grips(&m);
  cut_notch(&m);
  return m;
}

}  // namespace repose
