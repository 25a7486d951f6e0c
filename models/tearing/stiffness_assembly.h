#pragma once
// The implicit integrator's assembly of its stiffness and dashpot terms
// (implicit_integrator.h) into one of two stores: Eigen's compressed
// double matrix of the free system (CscTarget, the places of each block
// found once), or the multigrid smoother's float 3 x 3 block copy of it
// (BlockTarget, vertex_block_matrix.h), filled straight on the steps that
// keep the hierarchy, with no double matrix in between. Block index:
// for_each_block_place's (implicit_integrator.cpp).

#include <algorithm>
#include <array>
#include <vector>

#include <xmmintrin.h>

#include <Eigen/Core>

#include "models/tearing/sheet_forces.h"

namespace repose {

// The bending terms' stencil: term t couples a, b, c by kb w_t c_p c_q I.
constexpr double kBendingCoefficient[3] = {1.0, -2.0, 1.0};

// Eigen's column-major values: per block, per column q of it, the place of
// the first free row of its row vertex (the others follow).
struct CscTarget {
  const std::vector<std::array<int, 3>>& block_place;
  double* values;
  // entry (p, q) of block index, p's row row_offset below the vertex's first free row
  void entry(int index, int, int q, int row_offset, double value) {
    values[block_place[static_cast<std::size_t>(index)][static_cast<std::size_t>(q)] + row_offset] += value;
  }
  // a block between vertices free in every axis
  void block(int index, const Eigen::Matrix3d& m) {
    const std::array<int, 3>& place = block_place[static_cast<std::size_t>(index)];
    for (int q = 0; q < 3; ++q) {
      double* column = values + place[static_cast<std::size_t>(q)];
      for (int p = 0; p < 3; ++p) column[p] += m(p, q);
    }
  }
  // a spring's four blocks first + 0..3 between vertices free in every
  // axis: m, m, -m, -m
  void spring_blocks(int first, const Eigen::Matrix3d& m) {
    block(first, m);
    block(first + 1, m);
    block(first + 2, -m);
    block(first + 3, -m);
  }
  // value times the identity onto a block between vertices free in every axis
  void diagonal(int index, double value) {
    const std::array<int, 3>& place = block_place[static_cast<std::size_t>(index)];
    for (int axis = 0; axis < 3; ++axis) values[place[static_cast<std::size_t>(axis)] + axis] += value;
  }
};

// Row-major float 3 x 3 blocks: per block index, its block in values
// (k >= 0: values + 9 k), or a scalar block k I (-2 - s: the float at
// scalars + s; VertexBlockMatrix's identity couplings, only ever given
// multiples of the identity).
struct BlockTarget {
  const std::vector<int>& block_index;
  float* values;
  float* scalars = nullptr;
  float* at(int index) { return values + 9 * static_cast<std::ptrdiff_t>(block_index[static_cast<std::size_t>(index)]); }
  float* scalar(int index) {
    const int k = block_index[static_cast<std::size_t>(index)];
    return k <= -2 ? scalars + (-2 - k) : nullptr;
  }
  void entry(int index, int p, int q, int, double value) {
    if (float* s = scalar(index)) {
      if (p == 0 && q == 0) *s += static_cast<float>(value);  // (1, 1) and (2, 2) the same, the rest 0
      return;
    }
    at(index)[3 * p + q] += static_cast<float>(value);
  }
  void block(int index, const Eigen::Matrix3d& m) {
    float* b = at(index);
    for (int p = 0; p < 3; ++p) {
      for (int q = 0; q < 3; ++q) b[3 * p + q] += static_cast<float>(m(p, q));
    }
  }
  // as CscTarget's, m rounded to float once; each block's entries 0-3 and
  // 4-7 four at a time (SSE, part of every x86-64), the same float sums
  // and differences as one at a time. The
  // spring's blocks are distinct, so their order does not matter.
  void spring_blocks(int first, const Eigen::Matrix3d& m) {
    alignas(16) float f[12] = {};
    for (int p = 0; p < 3; ++p) {
      for (int q = 0; q < 3; ++q) f[3 * p + q] = static_cast<float>(m(p, q));
    }
    const __m128 low = _mm_load_ps(f), high = _mm_load_ps(f + 4);
    for (int k = 0; k < 4; ++k) {
      float* b = at(first + k);
      if (k < 2) {
        _mm_storeu_ps(b, _mm_add_ps(_mm_loadu_ps(b), low));
        _mm_storeu_ps(b + 4, _mm_add_ps(_mm_loadu_ps(b + 4), high));
        b[8] += f[8];
      } else {
        _mm_storeu_ps(b, _mm_sub_ps(_mm_loadu_ps(b), low));
        _mm_storeu_ps(b + 4, _mm_sub_ps(_mm_loadu_ps(b + 4), high));
        b[8] -= f[8];
      }
    }
  }
  void diagonal(int index, double value) {
    if (float* s = scalar(index)) {
      *s += static_cast<float>(value);
      return;
    }
    float* b = at(index);
    for (int axis = 0; axis < 3; ++axis) b[4 * axis] += static_cast<float>(value);
  }
};

// Adds -dt^2 K + dt C (the stiffness and dashpot blocks, into Target's
// storage; C = beta (K's axial and bending parts),
// SheetSpec::stiffness_damping_s) to the left and dt K v_n to the right
// (the dashpots' force at v_n is in the step's forces), held dv moved right.
template <class Target>
struct StiffnessAssembly {
  const std::vector<int>& free_index;
  const std::vector<int>& first_row;
  const std::vector<char>& all_free;
  Target target;
  Eigen::VectorXd* rhs;
  Eigen::Map<const Eigen::VectorXd> v0;
  const Eigen::VectorXd& dv_all;
  double dt2;
  double dt_beta;  // dt x stiffness_damping_s
  // false: the bending and twist terms add to the right-hand side only
  // (their blocks, constant while no cell tears, are in the store already)
  bool constant_blocks = true;

  // any block, any vertices: held rows skipped, held columns to the right;
  // block of -K, left its block in the system (dt^2 block + dt C's)
  void add_block(int index, int va, int vb, const Eigen::Matrix3d& block, const Eigen::Matrix3d& left,
                 bool to_store = true) {
    const int row0 = first_row[static_cast<std::size_t>(va)];
    for (int p = 0; p < 3; ++p) {
      const int row = free_index[static_cast<std::size_t>(3 * va + p)];
      if (row < 0) continue;
      for (int q = 0; q < 3; ++q) {
        const double kpq = block(p, q);  // of -K
        if (kpq == 0.0) continue;        // six of a bending block's nine (C is zero where K is)
        (*rhs)[row] -= dt2 * kpq * v0[3 * vb + q];
        if (free_index[static_cast<std::size_t>(3 * vb + q)] >= 0) {
          if (to_store) target.entry(index, p, q, row - row0, left(p, q));
        } else {
          (*rhs)[row] -= left(p, q) * dv_all[3 * vb + q];
        }
      }
    }
  }
  bool free(int v) const { return all_free[static_cast<std::size_t>(v)] != 0; }
  Eigen::VectorBlock<Eigen::VectorXd, 3> rhs_of(int v) { return rhs->segment<3>(first_row[static_cast<std::size_t>(v)]); }

  void add_spring(int first, int a, int b, const Eigen::Matrix3d& h, const Eigen::Matrix3d& axial) {
    const Eigen::Matrix3d scaled = dt2 * h;
    const Eigen::Matrix3d left = dt_beta > 0.0 ? Eigen::Matrix3d(scaled + dt_beta * axial) : scaled;
    if (!(free(a) && free(b))) {
      add_block(first, a, a, h, left);
      add_block(first + 1, b, b, h, left);
      add_block(first + 2, a, b, -h, -left);
      add_block(first + 3, b, a, -h, -left);
      return;
    }
    const Eigen::Vector3d pull = scaled * (v0.segment<3>(3 * b) - v0.segment<3>(3 * a));
    rhs_of(a) += pull;
    rhs_of(b) -= pull;
    target.spring_blocks(first, left);
  }

  // A spring of constant ks and rest length rest_length between a and b,
  // d = x_b - x_a (not 0): add_spring's h = ks (n n^T + g (I - n n^T)),
  // g = max(0, 1 - rest_length / |d|), axial = ks n n^T, n = d / |d|,
  // between free vertices from n and two coefficients (its blocks
  // alpha n n^T + gamma I, its pull dt^2 ks ((1 - g) n (n . dv) + g dv),
  // no 3 x 3 product); with a held axis through add_spring.
  void add_spring_along(int first, int a, int b, const Eigen::Vector3d& d, double ks, double rest_length) {
    const double length = d.norm();
    const Eigen::Vector3d n = d / length;
    const double g = std::max(0.0, 1.0 - rest_length / length);
    if (!(free(a) && free(b))) {
      Eigen::Matrix3d axial, h;
      for (int q = 0; q < 3; ++q) {
        for (int p = 0; p < 3; ++p) {
          const double npq = n[p] * n[q];
          axial(p, q) = ks * npq;
          h(p, q) = ks * (npq + g * ((p == q ? 1.0 : 0.0) - npq));
        }
      }
      add_spring(first, a, b, h, axial);
      return;
    }
    const double alpha = dt2 * ks * (1.0 - g) + dt_beta * ks, gamma = dt2 * ks * g;
    const Eigen::Vector3d dv = v0.segment<3>(3 * b) - v0.segment<3>(3 * a);
    const Eigen::Vector3d pull = (dt2 * ks) * ((1.0 - g) * n.dot(dv) * n + g * dv);
    rhs_of(a) += pull;
    rhs_of(b) -= pull;
    Eigen::Matrix3d left;
    for (int q = 0; q < 3; ++q) {
      for (int p = 0; p < 3; ++p) left(p, q) = alpha * n[p] * n[q] + (p == q ? gamma : 0.0);
    }
    target.spring_blocks(first, left);
  }

  // A bending term (kBendingCoefficient over three vertices along a mesh
  // line) and a cell's twist term (sheet_model.h; kTwistCoefficient over its
  // corners): blocks (v_p, v_q) of -K are k c_p c_q I, constant.
  void add_bending(int first, const std::array<int, 3>& v, double kb) { add_stencil(first, v, kBendingCoefficient, kb); }
  void add_twist(int first, const std::array<int, 4>& v, double kt) { add_stencil(first, v, kTwistCoefficient, kt); }

  // A term of energy k/2 |sum_q c_q x_{v_q}|^2, its blocks numbered
  // first + N p + q.
  template <std::size_t N>
  void add_stencil(int first, const std::array<int, N>& v, const double (&c)[N], double k) {
    const int n = static_cast<int>(N);
    const double left_scale = dt2 + dt_beta;  // -dt^2 K + dt beta K on the term
    bool all_free_corners = true;
    for (const int vertex : v) all_free_corners = all_free_corners && free(vertex);
    if (!all_free_corners) {
      for (int p = 0; p < n; ++p) {
        for (int q = 0; q < n; ++q) {
          const Eigen::Matrix3d block = k * c[p] * c[q] * Eigen::Matrix3d::Identity();
          add_block(first + n * p + q, v[static_cast<std::size_t>(p)], v[static_cast<std::size_t>(q)], block,
                    left_scale * block, constant_blocks);
        }
      }
      return;
    }
    // K v_n of the term on vertex p: k c_p sum_q c_q v_q
    Eigen::Vector3d combination = Eigen::Vector3d::Zero();
    for (int q = 0; q < n; ++q) combination += c[q] * v0.segment<3>(3 * v[static_cast<std::size_t>(q)]);
    for (int p = 0; p < n; ++p) {
      rhs_of(v[static_cast<std::size_t>(p)]) -= (dt2 * k * c[p]) * combination;
      if (!constant_blocks) continue;
      const double left_p = left_scale * k * c[p];
      for (int q = 0; q < n; ++q) target.diagonal(first + n * p + q, left_p * c[q]);
    }
  }
};

}  // namespace repose
