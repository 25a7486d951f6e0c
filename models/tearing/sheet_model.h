#pragma once
// The sheet's fixed description (the seed paper's section 3.2): a single
// layer of (cells_x + 1) x (cells_y + 1) vertices carrying the mass, square
// cells whose edges and diagonals are springs, and bending terms along the
// mesh lines. Built once from a SheetSpec and its fibre images; what a run
// changes is SheetState, what a fit changes SheetParams.
//
// Springs belong to cells: each cell contributes half an edge spring to each
// of its four edges (a shared edge gets both halves) and a full spring to
// each diagonal, all scaled by w^p, w the cell's relative fibre density
// (mean over the cell of the composite image, divided by the mean over the
// sheet: "the more fibre clumps near a spring, the larger its constant") and
// p = SheetSpec::stiffness_density_exponent (the seed gives no law; p = 1 is
// proportional, larger p sharpens the contrast between clumps and the gaps
// between them, which the seed's predecessor made strong). With
// k_edge = 3/4 E t and k_diagonal = 3/8 E t this lattice is isotropic with
// Poisson's ratio 1/3 and 2-D Young's modulus
//   E_2D = k_e (k_e + 2 k_d) / (k_e + k_d) = E t
// under uniform strain, for any cell size, and the half-strength boundary
// edges make the uniform strain an exact equilibrium of a finite sheet with
// free edges (tests/models/tearing/uniaxial_stiffness_test.cpp).
//
// Tearing removes a whole cell (all its springs at once, the vertices stay),
// which is what the seed does; with springs owned by cells this is removing
// the cell's share of each edge, so the sheet left is the union of intact
// cells.
//
// Departure from the seed: its "bending springs between opposite edges" are
// here the discrete second difference along each mesh line, energy
// 1/2 (D / h^2) |x_a - 2 x_b + x_c|^2 for three consecutive vertices a, b, c.
// A Provot skip spring (a to c) would also stiffen the sheet in plane; the
// second difference vanishes under any affine deformation, so it resists
// folding and leaves E_2D as above. A bending term acts while both of its
// edges are held by at least one intact cell.
//
// Departure from the seed, optional (SheetSpec::twist_stiffness): the
// second differences along the mesh lines see w_xx and w_yy only (a
// smooth out-of-plane w gives h^2 w_xx, one term per h^2 per direction,
// so D/2 (w_xx^2 + w_yy^2)); a twist w = kappa x y is linear along every
// mesh line and costs nothing, a zero-energy mode of the lattice. In
// plate terms they are the orthotropic D11 = D22 = D, D12 = D66 = 0, which
// is no isotropic plate for any Poisson's ratio (isotropy needs
// D12 + 2 D66 = D): a roll about a diagonal costs half of one about a mesh
// line, and the saddle along the diagonals (the twist) nothing. The twist
// term adds, per intact cell with corners 00, 10, 11, 01, the mixed
// difference Delta = x00 - x10 + x11 - x01 (= h^2 w_xy, exactly for any
// quadratic w; 0 under any affine map, so E_2D stands, and for a rigid
// motion) with energy 1/2 k_t w |Delta|^2, k_t = 2 D / h^2 and w the
// cell's stiffness factor: D w_xy^2 per area, i.e. D66 = D/2, and the
// sheet becomes the isotropic Kirchhoff plate of Poisson's ratio 0,
// D/2 (w_xx^2 + w_yy^2 + 2 w_xy^2); a twist w = kappa x y stores
// D kappa^2 A. It goes with its cell when the cell tears; the energy it
// held then is not counted as fracture energy (that is the springs'), but
// kept apart (SheetState::torn_twist_energy_j, the ledger's torn_twist).
//
// Departure from the seed, optional: a cell's tear strain may follow its
// fibre density too (tear_strain x w^q, q = tear_strain_density_exponent;
// q = 0 is the seed's single limit), so that the gaps between clumps are
// weaker as well as softer.
//
// Vertex masses are grammage x cell area / 4 x w summed over the vertex's
// cells, so the sheet's mass is grammage x area exactly.

#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "models/tearing/fibre_image.h"
#include "models/tearing/sheet_spec.h"

namespace repose {

// Three consecutive vertices along a mesh line and the cells on either side
// of its two edges (-1 where the sheet ends).
struct BendingTerm {
  int a = 0, b = 0, c = 0;
  std::array<int, 2> cells_ab{-1, -1};
  std::array<int, 2> cells_bc{-1, -1};
  double weight = 1.0;  // mean relative fibre density of those cells
};

struct SheetModel {
  SheetSpec spec;
  int cells_x = 0, cells_y = 0;
  double cell_size_m = 0.0;
  Eigen::Matrix3Xd rest_positions;  // 3 x vertex_count
  Eigen::VectorXd mass_kg;          // vertex_count
  Eigen::VectorXd cell_weight;      // cell_count, relative fibre density w (mean 1)
  Eigen::VectorXd cell_stiffness;   // cell_count, w^stiffness_density_exponent
  Eigen::VectorXd cell_tear_factor;  // cell_count, w^tear_strain_density_exponent
  std::vector<BendingTerm> bending;
  // Per vertex: bit a set when axis a (x, y, z) is moved by a grip.
  std::vector<std::uint8_t> held_axes;
  std::vector<int> grip_of_vertex;  // -1 when free
  std::vector<int> notch_cells;     // torn before the first step

  int vertex_count() const { return static_cast<int>(mass_kg.size()); }
  int cell_count() const { return cells_x * cells_y; }
  int vertex(int i, int j) const { return j * (cells_x + 1) + i; }
  int cell(int i, int j) const { return j * cells_x + i; }
  // The cell's corners, counter-clockwise from its lower-left.
  std::array<int, 4> corners(int cell_index) const;
};

// Validates the spec; the images must cover the sheet (fibre_image.h).
SheetModel build_sheet_model(const SheetSpec& spec, const FibreImages& images);

}  // namespace repose
