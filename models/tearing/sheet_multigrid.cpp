#include "models/tearing/sheet_multigrid.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <utility>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/core/config/fields.h"
#include "models/tearing/block_transfer.h"
#include "models/tearing/galerkin_product.h"

namespace repose {

namespace {

// A fine node's coarse neighbours along one grid line of n nodes: the
// coarse nodes are the even ones and the last; a fine node between two
// takes half of each.
struct LineWeights {
  int first = 0, second = -1;  // coarse node indices, second -1 when none
  double first_weight = 1.0;
};

// the even nodes and, when it is odd, the last
int coarse_line_count(int n) { return n <= 2 ? n : (n + 1) / 2 + (n % 2 == 0 ? 1 : 0); }

LineWeights line_weights(int n, int i) {
  if (n <= 2) return {i, -1, 1.0};  // too short to halve: every node stays
  const int last = coarse_line_count(n) - 1;
  if (i == n - 1) return {last, -1, 1.0};
  if (i % 2 == 0) return {i / 2, -1, 1.0};
  return {(i - 1) / 2, (i + 1) / 2, 0.5};
}

// One level's grid: vertices_x x vertices_y vertices, per (vertex, axis)
// its unknown or -1.
struct Grid {
  int vertices_x = 0, vertices_y = 0;
  std::vector<int> index;
  int count = 0;
};

// 1 / sum_j |a_ij| per row: the l1-Jacobi smoother's diagonal, which
// is at least a in the SPD sense, so its sweeps converge without a weight.
Eigen::VectorXd inverse_l1_rows(const Eigen::SparseMatrix<double>& a) {
  Eigen::VectorXd inverse(a.cols());
  for (int i = 0; i < a.cols(); ++i) {
    double sum = 0.0;
    for (int k = a.outerIndexPtr()[i]; k < a.outerIndexPtr()[i + 1]; ++k) sum += std::abs(a.valuePtr()[k]);
    REPOSE_DEMAND(sum > 0.0);
    inverse[i] = 1.0 / sum;
  }
  return inverse;
}

}  // namespace

struct SheetMultigrid::Level {
  Eigen::SparseMatrix<double> interpolation;  // finer x this level's unknowns
  Eigen::SparseMatrix<double> restriction;    // its transpose (l1-Jacobi only)
  // the same between the finer level's block vectors and this one's
  BlockTransfer transfer;
  Eigen::SparseMatrix<double> matrix;         // P^T A_finer P
  VertexBlockMatrix blocks;                   // matrix in float 3 x 3 blocks (Gauss-Seidel)
  Eigen::VectorXd inverse_l1;                 // inverse_l1_rows(matrix) (l1-Jacobi only)
  Grid grid;
};

void SheetMultigridOptions::validate() const {
  if (coarsest_unknowns < 1) {
    throw FieldError("coarsest_unknowns", "a count >= 1", fmt::format("{}", coarsest_unknowns));
  }
  if (smoothing_sweeps < 1) {
    throw FieldError("smoothing_sweeps", "a count >= 1", fmt::format("{}", smoothing_sweeps));
  }
}

SheetMultigrid::SheetMultigrid(int vertices_x, int vertices_y, std::vector<int> free_index, int free_count,
                               const SheetMultigridOptions& options)
    : options_(options), vertices_x_(vertices_x), vertices_y_(vertices_y), free_count_(free_count),
      free_index_(std::move(free_index)) {
  options_.validate();
  REPOSE_DEMAND(vertices_x >= 1 && vertices_y >= 1);
  REPOSE_DEMAND(static_cast<int>(free_index_.size()) == 3 * vertices_x * vertices_y);
}

SheetMultigrid::~SheetMultigrid() = default;

namespace {

// A fine unknown's interpolation: coarse candidates (3 (J X + I) + axis)
// and weights.
using Stencil = std::vector<std::pair<int, double>>;

// How strongly vertex u pulls on vertex v: minus the trace of their block
// over the axes both have free (springs and bending couple neighbours
// negatively), 0 across torn springs; -1 when no axis is free in both.
double coupling(const Eigen::SparseMatrix<double>& a, const Grid& grid, int u, int v) {
  double sum = 0.0;
  bool any = false;
  for (int axis = 0; axis < 3; ++axis) {
    const int row = grid.index[static_cast<std::size_t>(3 * u + axis)];
    const int col = grid.index[static_cast<std::size_t>(3 * v + axis)];
    if (row < 0 || col < 0) continue;
    any = true;
    sum -= a.coeff(row, col);
  }
  return any ? std::max(0.0, sum) : -1.0;
}

// The neighbours' stencils (coupling of `vertex` to the neighbour, its
// stencil) mixed by those couplings; a held neighbour (coupling -1) pulls
// as hard as the others on average; empty when nothing couples (a vertex
// left alone by tears: its mass only, which the smoother handles).
Stencil mixed_stencil(std::initializer_list<std::pair<double, const Stencil*>> neighbours) {
  double known = 0.0;
  int known_count = 0;
  for (const auto& neighbour : neighbours) {
    if (neighbour.first >= 0.0) known += neighbour.first, ++known_count;
  }
  double total = 0.0;
  Stencil mixed;
  mixed.reserve(8);  // at most four neighbours of two entries
  for (const auto& [strength, stencil] : neighbours) {
    const double w = strength >= 0.0 ? strength : (known_count > 0 ? known / known_count : 1.0);
    total += w;
    for (const auto& [col, weight] : *stencil) mixed.emplace_back(col, w * weight);
  }
  if (!(total > 0.0)) return {};
  for (auto& entry : mixed) entry.second /= total;
  return mixed;
}

// Per fine unknown, its interpolation from the coarse grid of `fine` (with
// coarse_vertices_x vertices a line), candidates not yet compacted. A fine node on a coarse line
// takes its two coarse neighbours weighted by its coupling to each; a node
// in the middle of a coarse cell takes its four edge neighbours' stencils so
// weighted. Held neighbours count in the weights' sum (they pull towards
// zero correction), torn springs couple nothing, so a tear does not smear
// the coarse correction across it; on an intact uniform sheet it is bilinear.
std::vector<Stencil> coarse_stencils(const Grid& fine, const Eigen::SparseMatrix<double>& a, int coarse_vertices_x) {
  const int nx = fine.vertices_x, ny = fine.vertices_y;
  const auto row_of = [&](int i, int j, int axis) { return fine.index[static_cast<std::size_t>(3 * (j * nx + i) + axis)]; };
  std::vector<Stencil> stencils(static_cast<std::size_t>(3 * nx * ny));
  // pass 0 fills the nodes on a coarse line, pass 1 the cell middles
  for (int pass = 0; pass < 2; ++pass) {
    for (int j = 0; j < ny; ++j) {
      const LineWeights wy = line_weights(ny, j);
      for (int i = 0; i < nx; ++i) {
        const LineWeights wx = line_weights(nx, i);
        const bool between_x = wx.second >= 0, between_y = wy.second >= 0;
        if ((between_x && between_y) != (pass == 1)) continue;
        const int v = j * nx + i;
        if (row_of(i, j, 0) < 0 && row_of(i, j, 1) < 0 && row_of(i, j, 2) < 0) continue;
        // the vertex's couplings to its neighbours, once for its three axes
        const double left = between_x ? coupling(a, fine, v, v - 1) : 0.0;
        const double right = between_x ? coupling(a, fine, v, v + 1) : 0.0;
        const double down = between_y ? coupling(a, fine, v, v - nx) : 0.0;
        const double up = between_y ? coupling(a, fine, v, v + nx) : 0.0;
        for (int axis = 0; axis < 3; ++axis) {
          if (row_of(i, j, axis) < 0) continue;
          Stencil& stencil = stencils[static_cast<std::size_t>(3 * v + axis)];
          const auto coarse_node = [&](int ci, int cj) {
            return Stencil{{3 * (cj * coarse_vertices_x + ci) + axis, 1.0}};
          };
          if (!between_x && !between_y) {
            stencil = coarse_node(wx.first, wy.first);
          } else if (between_x && !between_y) {
            const Stencil first = coarse_node(wx.first, wy.first), second = coarse_node(wx.second, wy.first);
            stencil = mixed_stencil({{left, &first}, {right, &second}});
          } else if (!between_x) {
            const Stencil first = coarse_node(wx.first, wy.first), second = coarse_node(wx.first, wy.second);
            stencil = mixed_stencil({{down, &first}, {up, &second}});
          } else {
            const auto edge = [&](int u) { return &stencils[static_cast<std::size_t>(3 * u + axis)]; };
            stencil = mixed_stencil({{left, edge(v - 1)}, {right, edge(v + 1)}, {down, edge(v - nx)}, {up, edge(v + nx)}});
          }
        }
      }
    }
  }
  return stencils;
}

// The interpolation from the coarse grid of `fine` into it, and that coarse
// grid (unknowns no fine row reaches dropped).
std::pair<Eigen::SparseMatrix<double>, Grid> interpolation_from_coarse(const Grid& fine,
                                                                       const Eigen::SparseMatrix<double>& a) {
  Grid coarse;
  coarse.vertices_x = coarse_line_count(fine.vertices_x);
  coarse.vertices_y = coarse_line_count(fine.vertices_y);
  const std::vector<Stencil> stencils = coarse_stencils(fine, a, coarse.vertices_x);
  // compact the coarse unknowns some fine row reaches
  const int candidates = 3 * coarse.vertices_x * coarse.vertices_y;
  std::vector<Eigen::Triplet<double>> triplets;
  std::vector<char> reached(static_cast<std::size_t>(candidates), 0);
  for (std::size_t k = 0; k < stencils.size(); ++k) {
    for (const auto& [col, weight] : stencils[k]) {
      if (weight == 0.0) continue;
      triplets.emplace_back(fine.index[k], col, weight);
      reached[static_cast<std::size_t>(col)] = 1;
    }
  }
  coarse.index.assign(static_cast<std::size_t>(candidates), -1);
  for (int k = 0; k < candidates; ++k) {
    if (reached[static_cast<std::size_t>(k)]) coarse.index[static_cast<std::size_t>(k)] = coarse.count++;
  }
  for (Eigen::Triplet<double>& t : triplets) {
    t = Eigen::Triplet<double>(t.row(), coarse.index[static_cast<std::size_t>(t.col())], t.value());
  }
  Eigen::SparseMatrix<double> p(fine.count, coarse.count);
  p.setFromTriplets(triplets.begin(), triplets.end());
  p.makeCompressed();
  return {std::move(p), std::move(coarse)};
}

}  // namespace

void SheetMultigrid::rebuild(const Eigen::SparseMatrix<double>& system) {
  REPOSE_DEMAND(system.rows() == free_count_ && system.cols() == free_count_);
  levels_.clear();
  // the fine pattern is the system's, fixed: its block copy is made once,
  // later rebuilds only gather the values
  if (fine_blocks_.has_pattern_of(system)) {
    fine_blocks_.refresh(system);
  } else {
    fine_blocks_ = VertexBlockMatrix(system, free_index_);
  }
  const bool l1_jacobi = options_.smoother == SheetMultigridOptions::Smoother::kL1Jacobi;
  if (l1_jacobi) fine_inverse_l1_ = inverse_l1_rows(system);
  Grid grid{vertices_x_, vertices_y_, free_index_, free_count_};
  const Eigen::SparseMatrix<double>* matrix = &system;
  while (grid.count > options_.coarsest_unknowns && (grid.vertices_x > 2 || grid.vertices_y > 2)) {
    auto level = std::make_unique<Level>();
    std::tie(level->interpolation, level->grid) = interpolation_from_coarse(grid, *matrix);
    if (l1_jacobi) level->restriction = level->interpolation.transpose();
    level->matrix = galerkin_product(*matrix, level->interpolation, grid.index, level->grid.index);
    level->blocks = VertexBlockMatrix(level->matrix, level->grid.index);
    if (l1_jacobi) level->inverse_l1 = inverse_l1_rows(level->matrix);
    const VertexBlockMatrix& finer = levels_.empty() ? fine_blocks_ : levels_.back()->blocks;
    level->transfer = BlockTransfer(level->interpolation, finer.block_place_of_rows(), level->blocks.block_place_of_rows(),
                                    finer.block_rows(), level->blocks.block_rows());
    grid = level->grid;
    levels_.push_back(std::move(level));
    matrix = &levels_.back()->matrix;
  }
  work_.assign(levels_.size(), Work{});
  coarsest_ = std::make_unique<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>>(*matrix);
  REPOSE_DEMAND(coarsest_->info() == Eigen::Success);
}

void SheetMultigrid::prepare_fine_pattern(const Eigen::SparseMatrix<double>& pattern,
                                          const std::vector<std::pair<int, int>>& identity_pairs) {
  REPOSE_DEMAND(pattern.rows() == free_count_ && pattern.cols() == free_count_);
  fine_blocks_ = VertexBlockMatrix(pattern, free_index_, false, identity_pairs);
}

bool SheetMultigrid::built() const { return coarsest_ != nullptr; }

int SheetMultigrid::level_count() const { return 1 + static_cast<int>(levels_.size()); }

Eigen::VectorXd SheetMultigrid::apply(const Eigen::SparseMatrix<double>& system, const Eigen::VectorXd& r) const {
  REPOSE_DEMAND(built() && system.rows() == free_count_ && r.size() == free_count_);
  if (options_.smoother == SheetMultigridOptions::Smoother::kL1Jacobi) return cycle(0, system, r);
  Eigen::VectorXd z;
  apply_blocks(fine_blocks_.to_blocks(r), &z);
  return fine_blocks_.from_blocks(z);
}

void SheetMultigrid::apply_blocks(const Eigen::VectorXd& r, Eigen::VectorXd* z, Eigen::VectorXd* az) const {
  REPOSE_DEMAND(built() && options_.smoother == SheetMultigridOptions::Smoother::kGaussSeidel &&
                r.size() == 3 * fine_blocks_.block_rows() && z != &r && az != &r && az != z);
  cycle_blocks(0, r, z, az);
}

void SheetMultigrid::cycle_blocks(std::size_t level, const Eigen::VectorXd& b, Eigen::VectorXd* x,
                                  Eigen::VectorXd* ax) const {
  const VertexBlockMatrix& blocks = level == 0 ? fine_blocks_ : levels_[level - 1]->blocks;
  if (level == levels_.size()) {
    blocks.to_blocks(coarsest_->solve(blocks.from_blocks(b)), x);
    if (ax) blocks.product(*x, ax);
    return;
  }
  const int sweeps = options_.smoothing_sweeps;
  if (sweeps == 1 && options_.single_precision_sweeps) {
    cycle_in_float(level, b, x, ax);
    return;
  }
  const Level& coarse = *levels_[level];
  Work& work = work_[level];
  if (sweeps == 1) {
    // one sweep from zero: its residual from the blocks it reads
    blocks.sweep_from_zero_with_residual(b, x, &work.residual);
  } else {
    x->setZero(b.size());
    for (int s = 0; s < sweeps; ++s) blocks.gauss_seidel_sweep(b, true, s == 0, x);
    blocks.residual(b, *x, &work.residual);
  }
  coarse.transfer.restrict_to(work.residual, &work.coarse_b);
  cycle_blocks(level + 1, work.coarse_b, &work.coarse_x, nullptr);
  coarse.transfer.add_interpolated(work.coarse_x, x);
  for (int s = 0; s + 1 < sweeps; ++s) blocks.gauss_seidel_sweep(b, false, false, x);
  if (ax) {
    blocks.backward_sweep_with_product(b, x, ax);
  } else {
    blocks.gauss_seidel_sweep(b, false, false, x);
  }
}

namespace {

// block vectors (3 a vertex, double) to the float passes' (4 a vertex, the
// fourth 0) and back
void to_float(const Eigen::VectorXd& from, std::size_t size, AlignedFloats* to) {
  to->resize(size);
  float* out = to->data();
  const double* in = from.data();
  for (Eigen::Index v = 0; v < from.size() / 3; ++v, out += 4, in += 3) {
    out[0] = static_cast<float>(in[0]);
    out[1] = static_cast<float>(in[1]);
    out[2] = static_cast<float>(in[2]);
    out[3] = 0.0f;
  }
}

void to_double(const AlignedFloats& from, Eigen::Index size, Eigen::VectorXd* to) {
  to->resize(size);
  const float* in = from.data();
  double* out = to->data();
  for (Eigen::Index v = 0; v < size / 3; ++v, out += 3, in += 4) {
    out[0] = in[0];
    out[1] = in[1];
    out[2] = in[2];
  }
}

}  // namespace

void SheetMultigrid::cycle_in_float(std::size_t level, const Eigen::VectorXd& b, Eigen::VectorXd* x,
                                    Eigen::VectorXd* ax) const {
  const VertexBlockMatrix& blocks = level == 0 ? fine_blocks_ : levels_[level - 1]->blocks;
  const Level& coarse = *levels_[level];
  Work& w = work_[level];
  const std::size_t size = blocks.float_vector_size();
  to_float(b, size, &w.b);
  w.x.resize(size);
  w.float_residual.resize(size);
  blocks.sweep_from_zero_with_residual(w.b.data(), w.x.data(), w.float_residual.data());
  coarse.transfer.restrict_to(w.float_residual.data(), &w.coarse_b);
  cycle_blocks(level + 1, w.coarse_b, &w.coarse_x, nullptr);
  coarse.transfer.add_interpolated(w.coarse_x, w.x.data());
  if (ax) w.ax.resize(size);
  blocks.backward_sweep_with_product(w.b.data(), w.x.data(), ax ? w.ax.data() : nullptr);
  to_double(w.x, b.size(), x);
  if (ax) to_double(w.ax, b.size(), ax);
}

void SheetMultigrid::update_fine(const Eigen::SparseMatrix<double>& system) {
  REPOSE_DEMAND(built() && system.rows() == free_count_);
  fine_blocks_.refresh(system);
  if (options_.smoother == SheetMultigridOptions::Smoother::kL1Jacobi) fine_inverse_l1_ = inverse_l1_rows(system);
}

Eigen::VectorXd SheetMultigrid::cycle(std::size_t level, const Eigen::SparseMatrix<double>& matrix,
                                      const Eigen::VectorXd& r) const {
  if (level == levels_.size()) return coarsest_->solve(r);
  const Level& coarse = *levels_[level];
  const Eigen::VectorXd& inverse_l1 = level == 0 ? fine_inverse_l1_ : levels_[level - 1]->inverse_l1;
  Eigen::VectorXd x = inverse_l1.cwiseProduct(r);  // the first sweep from x = 0
  Eigen::VectorXd residual = r - matrix * x;
  for (int s = 1; s < options_.smoothing_sweeps; ++s) {
    x += inverse_l1.cwiseProduct(residual);
    residual = r - matrix * x;
  }
  x += coarse.interpolation * cycle(level + 1, coarse.matrix, coarse.restriction * residual);
  for (int s = 0; s < options_.smoothing_sweeps; ++s) x += inverse_l1.cwiseProduct(r - matrix * x);
  return x;
}

}  // namespace repose
