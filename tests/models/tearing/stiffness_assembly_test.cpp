// The implicit integrator's assembly of springs, bending and twist terms
// (stiffness_assembly.h): the documented blocks and right-hand side, the
// same system in Eigen's compressed store and in the float blocks, and
// held axes moved to the right-hand side exactly as eliminating them from
// the all-free system would.
#include "models/tearing/stiffness_assembly.h"

#include <algorithm>
#include <array>
#include <map>
#include <random>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include <gtest/gtest.h>

namespace repose {
namespace {

// A system over `vertices` vertices with the axes `held` (per degree of
// freedom 3 v + a) held, stored both ways: a dense column-major matrix of
// the free rows (CscTarget's places) and one float block per vertex pair
// (BlockTarget's), for blocks named in index order by `pairs`; the pairs
// in `scalar` stored as one float each (BlockTarget's scalar blocks, k I).
struct TwoStores {
  std::vector<int> free_index, first_row;
  std::vector<char> all_free;
  int free_count = 0;
  std::vector<std::array<int, 3>> block_place;  // per block index
  std::vector<double> dense;                    // free_count^2, column-major
  std::vector<int> block_index;                 // per block index: its slot
  std::vector<float> blocks;                    // 9 per slot, row-major
  std::vector<std::pair<int, int>> slot_pair;
  std::vector<float> scalars;  // per scalar slot
  std::vector<std::pair<int, int>> scalar_pair;

  TwoStores(int vertices, const std::vector<bool>& held, const std::vector<std::pair<int, int>>& pairs,
            const std::vector<std::pair<int, int>>& scalar = {}) {
    free_index.assign(static_cast<std::size_t>(3 * vertices), -1);
    first_row.assign(static_cast<std::size_t>(vertices), -1);
    all_free.assign(static_cast<std::size_t>(vertices), 1);
    for (int v = 0; v < vertices; ++v) {
      for (int a = 0; a < 3; ++a) {
        if (held[static_cast<std::size_t>(3 * v + a)]) {
          all_free[static_cast<std::size_t>(v)] = 0;
          continue;
        }
        if (first_row[static_cast<std::size_t>(v)] < 0) first_row[static_cast<std::size_t>(v)] = free_count;
        free_index[static_cast<std::size_t>(3 * v + a)] = free_count++;
      }
    }
    dense.assign(static_cast<std::size_t>(free_count * free_count), 0.0);
    std::map<std::pair<int, int>, int> slot_of;
    for (const auto& [a, b] : pairs) {
      std::array<int, 3> place = {-1, -1, -1};
      for (int q = 0; q < 3; ++q) {
        const int col = free_index[static_cast<std::size_t>(3 * b + q)];
        if (col >= 0 && first_row[static_cast<std::size_t>(a)] >= 0) {
          place[static_cast<std::size_t>(q)] = col * free_count + first_row[static_cast<std::size_t>(a)];
        }
      }
      block_place.push_back(place);
      if (std::find(scalar.begin(), scalar.end(), std::make_pair(a, b)) != scalar.end()) {
        block_index.push_back(-2 - static_cast<int>(scalar_pair.size()));
        scalar_pair.emplace_back(a, b);
        continue;
      }
      const auto [at, inserted] = slot_of.emplace(std::make_pair(a, b), static_cast<int>(slot_pair.size()));
      if (inserted) slot_pair.emplace_back(a, b);
      block_index.push_back(at->second);
    }
    blocks.assign(9 * slot_pair.size(), 0.0f);
    scalars.assign(scalar_pair.size(), 0.0f);
  }

  Eigen::MatrixXd csc_matrix() const { return Eigen::Map<const Eigen::MatrixXd>(dense.data(), free_count, free_count); }
  // the float blocks as a matrix over the free rows
  Eigen::MatrixXd block_matrix() const {
    Eigen::MatrixXd m = Eigen::MatrixXd::Zero(free_count, free_count);
    for (std::size_t s = 0; s < slot_pair.size(); ++s) {
      for (int p = 0; p < 3; ++p) {
        for (int q = 0; q < 3; ++q) {
          const int row = free_index[static_cast<std::size_t>(3 * slot_pair[s].first + p)];
          const int col = free_index[static_cast<std::size_t>(3 * slot_pair[s].second + q)];
          if (row >= 0 && col >= 0) m(row, col) += blocks[9 * s + static_cast<std::size_t>(3 * p + q)];
        }
      }
    }
    for (std::size_t s = 0; s < scalar_pair.size(); ++s) {
      for (int p = 0; p < 3; ++p) {
        const int row = free_index[static_cast<std::size_t>(3 * scalar_pair[s].first + p)];
        const int col = free_index[static_cast<std::size_t>(3 * scalar_pair[s].second + p)];
        if (row >= 0 && col >= 0) m(row, col) += scalars[s];
      }
    }
    return m;
  }
};

struct Assembled {
  Eigen::MatrixXd csc, block;
  Eigen::VectorXd rhs_csc, rhs_block;
};

// Runs `add` (given a StiffnessAssembly of either store) into both stores.
template <class Add>
Assembled assemble_both(TwoStores* s, const Eigen::VectorXd& v0, const Eigen::VectorXd& dv_all, double dt2,
                        double dt_beta, Add&& add) {
  Assembled out;
  out.rhs_csc = out.rhs_block = Eigen::VectorXd::Zero(s->free_count);
  const Eigen::Map<const Eigen::VectorXd> v0_map(v0.data(), v0.size());
  StiffnessAssembly<CscTarget> csc{s->free_index, s->first_row, s->all_free, {s->block_place, s->dense.data()},
                                   &out.rhs_csc,  v0_map,       dv_all,      dt2, dt_beta};
  add(&csc);
  StiffnessAssembly<BlockTarget> block{s->free_index,
                                       s->first_row,
                                       s->all_free,
                                       {s->block_index, s->blocks.data(), s->scalars.data()},
                                       &out.rhs_block, v0_map,      dv_all,      dt2, dt_beta};
  add(&block);
  out.csc = s->csc_matrix();
  out.block = s->block_matrix();
  return out;
}

Eigen::Matrix3d random_spd(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const Eigen::Vector3d n = Eigen::Vector3d(uniform(rng), uniform(rng), uniform(rng)).normalized();
  return 50.0 * n * n.transpose() + 7.0 * Eigen::Matrix3d::Identity();
}

Eigen::VectorXd random_vector(int n, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::VectorXd x(n);
  for (int i = 0; i < n; ++i) x[i] = uniform(rng);
  return x;
}

const std::vector<std::pair<int, int>> kSpringPairs = {{0, 0}, {1, 1}, {0, 1}, {1, 0}};

std::vector<std::pair<int, int>> bending_pairs() {
  std::vector<std::pair<int, int>> pairs;
  for (int p = 0; p < 3; ++p) {
    for (int q = 0; q < 3; ++q) pairs.emplace_back(p, q);
  }
  return pairs;
}

// The spring between two free vertices: blocks +-(dt^2 h + dt beta axial),
// right-hand side +-dt^2 h (v_b - v_a); the float store within rounding.
TEST(StiffnessAssembly, ASpringGivesItsDocumentedBlocksInBothStores) {
  std::mt19937_64 rng(1);
  const Eigen::Matrix3d h = random_spd(rng), axial = random_spd(rng);
  const double dt2 = 1e-4, dt_beta = 3e-5;
  TwoStores s(2, std::vector<bool>(6, false), kSpringPairs);
  const Eigen::VectorXd v0 = random_vector(6, rng), dv = Eigen::VectorXd::Zero(6);
  const Assembled a = assemble_both(&s, v0, dv, dt2, dt_beta, [&](auto* assembly) { assembly->add_spring(0, 0, 1, h, axial); });
  const Eigen::Matrix3d left = dt2 * h + dt_beta * axial;
  Eigen::MatrixXd expected(6, 6);
  expected << left, -left, -left, left;
  EXPECT_LT((a.csc - expected).norm(), 1e-15 * expected.norm());
  EXPECT_LT((a.block - expected).norm(), 1e-6 * expected.norm());
  const Eigen::Vector3d pull = dt2 * h * (v0.segment<3>(3) - v0.segment<3>(0));
  Eigen::VectorXd rhs(6);
  rhs << pull, -pull;
  EXPECT_LT((a.rhs_csc - rhs).norm(), 1e-15 * rhs.norm());
  EXPECT_EQ(a.rhs_csc, a.rhs_block);
}

// A spring given by its vertices' separation, constant and rest length is
// add_spring with its documented h and axial, stretched (geometric
// stiffness) and compressed (none), free and with held axes, in both stores.
TEST(StiffnessAssembly, ASpringAlongItsSeparationIsAddSpringWithItsDocumentedBlocks) {
  std::mt19937_64 rng(5);
  const double ks = 40.0, dt2 = 1e-4, dt_beta = 3e-5;
  const Eigen::VectorXd v0 = random_vector(6, rng), dv = random_vector(6, rng);
  const Eigen::Vector3d d(0.3, -0.2, 0.1);
  for (const double rest : {0.8 * d.norm(), 1.3 * d.norm()}) {
    const Eigen::Vector3d n = d.normalized();
    const double g = std::max(0.0, 1.0 - rest / d.norm());
    const Eigen::Matrix3d axial = ks * n * n.transpose();
    const Eigen::Matrix3d h = ks * (n * n.transpose() + g * (Eigen::Matrix3d::Identity() - n * n.transpose()));
    for (const unsigned mask : {0u, 0b000101u, 0b111000u}) {
      std::vector<bool> held(6);
      for (int k = 0; k < 6; ++k) held[static_cast<std::size_t>(k)] = (mask >> k) & 1u;
      TwoStores by_blocks(2, held, kSpringPairs), along(2, held, kSpringPairs);
      const Assembled expected = assemble_both(&by_blocks, v0, dv, dt2, dt_beta,
                                               [&](auto* assembly) { assembly->add_spring(0, 0, 1, h, axial); });
      const Assembled a = assemble_both(&along, v0, dv, dt2, dt_beta, [&](auto* assembly) {
        assembly->add_spring_along(0, 0, 1, d, ks, rest);
      });
      EXPECT_LT((a.csc - expected.csc).norm(), 1e-14 * expected.csc.norm()) << rest << " " << mask;
      EXPECT_LT((a.block - expected.block).norm(), 1e-6 * expected.block.norm()) << rest << " " << mask;
      EXPECT_LT((a.rhs_csc - expected.rhs_csc).norm(), 1e-14 * expected.rhs_csc.norm()) << rest << " " << mask;
      EXPECT_LT((a.rhs_block - expected.rhs_csc).norm(), 1e-14 * expected.rhs_csc.norm()) << rest << " " << mask;
    }
  }
}

// A bending term on three free vertices: blocks (dt^2 + dt beta) kb c_p c_q I.
TEST(StiffnessAssembly, ABendingTermGivesItsStencilInBothStores) {
  std::mt19937_64 rng(2);
  const double kb = 4.0, dt2 = 1e-4, dt_beta = 2e-5;
  TwoStores s(3, std::vector<bool>(9, false), bending_pairs());
  const Eigen::VectorXd v0 = random_vector(9, rng), dv = Eigen::VectorXd::Zero(9);
  const Assembled a = assemble_both(&s, v0, dv, dt2, dt_beta, [&](auto* assembly) { assembly->add_bending(0, {0, 1, 2}, kb); });
  const Eigen::Vector3d curvature = v0.segment<3>(0) - 2.0 * v0.segment<3>(3) + v0.segment<3>(6);
  Eigen::MatrixXd expected(9, 9);
  Eigen::VectorXd rhs(9);
  for (int p = 0; p < 3; ++p) {
    for (int q = 0; q < 3; ++q) {
      expected.block<3, 3>(3 * p, 3 * q) =
          (dt2 + dt_beta) * kb * kBendingCoefficient[p] * kBendingCoefficient[q] * Eigen::Matrix3d::Identity();
    }
    rhs.segment<3>(3 * p) = -dt2 * kb * kBendingCoefficient[p] * curvature;
  }
  EXPECT_LT((a.csc - expected).norm(), 1e-15 * expected.norm());
  EXPECT_LT((a.block - expected).norm(), 1e-6 * expected.norm());
  EXPECT_LT((a.rhs_csc - rhs).norm(), 1e-15 * rhs.norm());
  EXPECT_LT((a.rhs_block - rhs).norm(), 1e-15 * rhs.norm());
}

// The bending term's end blocks (0, 2) and (2, 0) kept as scalar blocks
// (the fine blocks' identity couplings): the same matrix, whether its
// vertices are all free or the middle one is held (the ends' blocks then
// come entry by entry).
TEST(StiffnessAssembly, ABendingTermsEndBlocksGoIntoScalarBlocks) {
  std::mt19937_64 rng(5);
  const double kb = 4.0, dt2 = 1e-4, dt_beta = 2e-5;
  const Eigen::VectorXd v0 = random_vector(9, rng), dv = random_vector(9, rng);
  for (const bool middle_held : {false, true}) {
    std::vector<bool> held(9, false);
    if (middle_held) held[4] = true;  // the middle vertex's y
    TwoStores full(3, held, bending_pairs()), scalar(3, held, bending_pairs(), {{0, 2}, {2, 0}});
    ASSERT_EQ(scalar.scalar_pair.size(), 2u);
    const auto add = [&](auto* assembly) { assembly->add_bending(0, {0, 1, 2}, kb); };
    const Assembled a = assemble_both(&full, v0, dv, dt2, dt_beta, add);
    const Assembled b = assemble_both(&scalar, v0, dv, dt2, dt_beta, add);
    EXPECT_EQ(b.block, a.block) << middle_held;
    EXPECT_EQ(b.rhs_block, a.rhs_block) << middle_held;
    EXPECT_FLOAT_EQ(scalar.scalars[0], static_cast<float>((dt2 + dt_beta) * kb)) << middle_held;
    EXPECT_FLOAT_EQ(scalar.scalars[1], static_cast<float>((dt2 + dt_beta) * kb)) << middle_held;
  }
}

// Holding axes (each mask of a spring's and a bending term's vertices in
// turn) is eliminating them from the all-free system with their dv known:
// A_ff dv_f = r_f - A_fh dv_h.
TEST(StiffnessAssembly, HeldAxesAreEliminatedFromTheAllFreeSystem) {
  std::mt19937_64 rng(3);
  const Eigen::Matrix3d h = random_spd(rng), axial = random_spd(rng);
  const double kb = 4.0, dt2 = 1e-4, dt_beta = 3e-5;
  const Eigen::VectorXd v0 = random_vector(9, rng), dv = random_vector(9, rng);
  const auto add = [&](auto* assembly) {
    assembly->add_spring(0, 0, 1, h, axial);
    assembly->add_bending(4, {0, 1, 2}, kb);
  };
  std::vector<std::pair<int, int>> pairs = kSpringPairs;
  for (const auto& pair : bending_pairs()) pairs.push_back(pair);
  TwoStores free_store(3, std::vector<bool>(9, false), pairs);
  const Assembled all = assemble_both(&free_store, v0, dv, dt2, dt_beta, add);
  for (const unsigned mask : {0b000000001u, 0b000000111u, 0b000111010u, 0b100000100u, 0b110101011u}) {
    std::vector<bool> held(9);
    for (int k = 0; k < 9; ++k) held[static_cast<std::size_t>(k)] = (mask >> k) & 1u;
    TwoStores s(3, held, pairs);
    const Assembled a = assemble_both(&s, v0, dv, dt2, dt_beta, add);
    std::vector<int> free_rows, held_rows;
    for (int k = 0; k < 9; ++k) (held[static_cast<std::size_t>(k)] ? held_rows : free_rows).push_back(k);
    const Eigen::MatrixXd a_ff = all.csc(free_rows, free_rows), a_fh = all.csc(free_rows, held_rows);
    const Eigen::VectorXd rhs = all.rhs_csc(free_rows) - a_fh * dv(held_rows);
    EXPECT_LT((a.csc - a_ff).norm(), 1e-15 * a_ff.norm()) << "mask " << mask;
    EXPECT_LT((a.block - a_ff).norm(), 1e-6 * a_ff.norm()) << "mask " << mask;
    EXPECT_LT((a.rhs_csc - rhs).norm(), 1e-14 * rhs.norm()) << "mask " << mask;
    EXPECT_LT((a.rhs_block - rhs).norm(), 1e-14 * rhs.norm()) << "mask " << mask;
  }
}

std::vector<std::pair<int, int>> twist_pairs() {
  std::vector<std::pair<int, int>> pairs;
  for (int p = 0; p < 4; ++p) {
    for (int q = 0; q < 4; ++q) pairs.emplace_back(p, q);
  }
  return pairs;
}

// A cell's twist term on four free vertices: blocks (dt^2 + dt beta) kt
// c_p c_q I, right-hand side -dt^2 kt c_p Delta(v0) (kTwistCoefficient);
// with axes held, the all-free system with them eliminated.
TEST(StiffnessAssembly, ATwistTermGivesItsStencilInBothStoresAndEliminatesHeldAxes) {
  std::mt19937_64 rng(4);
  const double kt = 6.0, dt2 = 1e-4, dt_beta = 2e-5;
  const Eigen::VectorXd v0 = random_vector(12, rng), dv = random_vector(12, rng);
  const auto add = [&](auto* assembly) { assembly->add_twist(0, {0, 1, 2, 3}, kt); };
  TwoStores free_store(4, std::vector<bool>(12, false), twist_pairs());
  const Assembled all = assemble_both(&free_store, v0, dv, dt2, dt_beta, add);
  Eigen::Vector3d twist = Eigen::Vector3d::Zero();
  for (int q = 0; q < 4; ++q) twist += kTwistCoefficient[q] * v0.segment<3>(3 * q);
  Eigen::MatrixXd expected(12, 12);
  Eigen::VectorXd rhs(12);
  for (int p = 0; p < 4; ++p) {
    for (int q = 0; q < 4; ++q) {
      expected.block<3, 3>(3 * p, 3 * q) =
          (dt2 + dt_beta) * kt * kTwistCoefficient[p] * kTwistCoefficient[q] * Eigen::Matrix3d::Identity();
    }
    rhs.segment<3>(3 * p) = -dt2 * kt * kTwistCoefficient[p] * twist;
  }
  EXPECT_LT((all.csc - expected).norm(), 1e-15 * expected.norm());
  EXPECT_LT((all.block - expected).norm(), 1e-6 * expected.norm());
  EXPECT_LT((all.rhs_csc - rhs).norm(), 1e-15 * rhs.norm());
  EXPECT_LT((all.rhs_block - rhs).norm(), 1e-15 * rhs.norm());
  for (const unsigned mask : {0b000000000001u, 0b000000111000u, 0b010001010100u, 0b111000000111u}) {
    std::vector<bool> held(12);
    for (int k = 0; k < 12; ++k) held[static_cast<std::size_t>(k)] = (mask >> k) & 1u;
    TwoStores s(4, held, twist_pairs());
    const Assembled a = assemble_both(&s, v0, dv, dt2, dt_beta, add);
    std::vector<int> free_rows, held_rows;
    for (int k = 0; k < 12; ++k) (held[static_cast<std::size_t>(k)] ? held_rows : free_rows).push_back(k);
    const Eigen::MatrixXd a_ff = all.csc(free_rows, free_rows), a_fh = all.csc(free_rows, held_rows);
    const Eigen::VectorXd r = all.rhs_csc(free_rows) - a_fh * dv(held_rows);
    EXPECT_LT((a.csc - a_ff).norm(), 1e-15 * a_ff.norm()) << "mask " << mask;
    EXPECT_LT((a.block - a_ff).norm(), 1e-6 * a_ff.norm()) << "mask " << mask;
    EXPECT_LT((a.rhs_csc - r).norm(), 1e-14 * r.norm()) << "mask " << mask;
    EXPECT_LT((a.rhs_block - r).norm(), 1e-14 * r.norm()) << "mask " << mask;
  }
}

}  // namespace
}  // namespace repose
