// VertexBlockMatrix's fused passes in single precision (vertex_block_matrix.h),
// four floats at a time with SSE2 (part of every x86-64, no build flag).
//
// Why: with double vectors each block entry was converted to double and
// multiplied on its own, ~25 scalar instructions a block and pass; the
// fine level's two passes took ~30 % of an implicit step at 200 x 200. Here
// a block row is one 4-wide load times x_j (also one load): the products of
// a block row's three rows go into three 4-wide sums, added across once
// per row. The vectors hold 4 floats a vertex (the fourth 0), aligned, so
// that every load of a vertex's entries reads what one store wrote: with 3
// a vertex, 4-wide loads that straddled two vertices' stores missed the
// store forwarding and the passes ran 2x slower than the double ones. Lane
// 3 of a block row's load reads the next entry (the last block's padding):
// it is dropped in the row sums and masked to 0 before any store. Scalar
// blocks (k I, vertex_block_matrix.h) are one broadcast times x_j; x's
// lane 3 is 0, so they keep it 0.
#include "models/tearing/vertex_block_matrix.h"

#include <xmmintrin.h>
#include <emmintrin.h>

#include "models/core/base/error.h"

namespace repose {

namespace {

// Two sets of three sums (even and odd blocks): one chain per sum stalled
// on the add's latency.
struct RowSums {
  __m128 a0 = _mm_setzero_ps(), a1 = _mm_setzero_ps(), a2 = _mm_setzero_ps();
  __m128 b0 = _mm_setzero_ps(), b1 = _mm_setzero_ps(), b2 = _mm_setzero_ps();
};

// The rows of block m times x_j into s0..s2 (lane 3 dropped later).
inline void gather_block(const float* m, const float* xj, __m128* s0, __m128* s1, __m128* s2) {
  const __m128 x = _mm_load_ps(xj);
  *s0 = _mm_add_ps(*s0, _mm_mul_ps(_mm_loadu_ps(m), x));
  *s1 = _mm_add_ps(*s1, _mm_mul_ps(_mm_loadu_ps(m + 3), x));
  *s2 = _mm_add_ps(*s2, _mm_mul_ps(_mm_loadu_ps(m + 6), x));
}

// sum_k A_ik x_k over blocks [begin, end) of a row, in memory order or
// against it (a backward sweep reads memory backwards: the hardware
// prefetcher follows one direction per stream), as (row 0, row 1, row 2, 0).
template <bool kDescending>
inline __m128 gather_blocks(const float* values, const int* column, int begin, int end, const float* x) {
  RowSums s;
  const int count = end - begin;
  const auto block = [&](int j) { return kDescending ? end - 1 - j : begin + j; };
  int j = 0;
  for (; j + 2 <= count; j += 2) {
    const int k0 = block(j), k1 = block(j + 1);
    gather_block(values + 9 * static_cast<std::ptrdiff_t>(k0), x + 4 * static_cast<std::ptrdiff_t>(column[k0]), &s.a0,
                 &s.a1, &s.a2);
    gather_block(values + 9 * static_cast<std::ptrdiff_t>(k1), x + 4 * static_cast<std::ptrdiff_t>(column[k1]), &s.b0,
                 &s.b1, &s.b2);
  }
  if (j < count) {
    const int k = block(j);
    gather_block(values + 9 * static_cast<std::ptrdiff_t>(k), x + 4 * static_cast<std::ptrdiff_t>(column[k]), &s.b0,
                 &s.b1, &s.b2);
  }
  __m128 r0 = _mm_add_ps(s.a0, s.b0), r1 = _mm_add_ps(s.a1, s.b1), r2 = _mm_add_ps(s.a2, s.b2);
  __m128 r3 = _mm_setzero_ps();
  _MM_TRANSPOSE4_PS(r0, r1, r2, r3);  // r_p now holds lane p of each row's sum; r3 (the lanes 3) dropped
  return _mm_and_ps(_mm_add_ps(_mm_add_ps(r0, r1), r2), _mm_castsi128_ps(_mm_set_epi32(0, -1, -1, -1)));
}

// sum_k a_k x_k over the scalar blocks [begin, end) of a row (a_k I each),
// in memory order or against it, two sums; lane 3 stays 0 (x's padding).
template <bool kDescending>
inline __m128 gather_scalars(const float* scalars, const int* column, int begin, int end, const float* x) {
  __m128 a = _mm_setzero_ps(), b = _mm_setzero_ps();
  const int count = end - begin;
  const auto block = [&](int j) { return kDescending ? end - 1 - j : begin + j; };
  int j = 0;
  for (; j + 2 <= count; j += 2) {
    const int k0 = block(j), k1 = block(j + 1);
    a = _mm_add_ps(a, _mm_mul_ps(_mm_set1_ps(scalars[k0]), _mm_load_ps(x + 4 * static_cast<std::ptrdiff_t>(column[k0]))));
    b = _mm_add_ps(b, _mm_mul_ps(_mm_set1_ps(scalars[k1]), _mm_load_ps(x + 4 * static_cast<std::ptrdiff_t>(column[k1]))));
  }
  if (j < count) {
    const int k = block(j);
    a = _mm_add_ps(a, _mm_mul_ps(_mm_set1_ps(scalars[k]), _mm_load_ps(x + 4 * static_cast<std::ptrdiff_t>(column[k]))));
  }
  return _mm_add_ps(a, b);
}

// y_j += a_k v over the scalar blocks [begin, end) of a row (v's lane 3 0).
inline void scatter_scalars(const float* scalars, const int* column, int begin, int end, __m128 v, float* y) {
  for (int k = begin; k < end; ++k) {
    float* yj = y + 4 * static_cast<std::ptrdiff_t>(column[k]);
    _mm_store_ps(yj, _mm_add_ps(_mm_load_ps(yj), _mm_mul_ps(_mm_set1_ps(scalars[k]), v)));
  }
}

// D_i^-1 s from its padded columns (lane 3 0).
inline __m128 times_inverse(const float* columns, __m128 s) {
  const __m128 x0 = _mm_mul_ps(_mm_loadu_ps(columns), _mm_shuffle_ps(s, s, 0x00));
  const __m128 x1 = _mm_mul_ps(_mm_loadu_ps(columns + 4), _mm_shuffle_ps(s, s, 0x55));
  const __m128 x2 = _mm_mul_ps(_mm_loadu_ps(columns + 8), _mm_shuffle_ps(s, s, 0xAA));
  return _mm_add_ps(_mm_add_ps(x0, x1), x2);
}

// y_j += A_ij^T v over blocks [begin, end) of row i: A_ij's rows scaled by
// v's lanes, lane 3 (the padding) kept 0.
inline void scatter_transposed(const float* values, const int* column, int begin, int end, __m128 v, float* y) {
  const __m128 v0 = _mm_shuffle_ps(v, v, 0x00), v1 = _mm_shuffle_ps(v, v, 0x55), v2 = _mm_shuffle_ps(v, v, 0xAA);
  const __m128 mask = _mm_castsi128_ps(_mm_set_epi32(0, -1, -1, -1));
  for (int k = begin; k < end; ++k) {
    const float* m = values + 9 * static_cast<std::ptrdiff_t>(k);
    float* yj = y + 4 * static_cast<std::ptrdiff_t>(column[k]);
    const __m128 t = _mm_add_ps(_mm_add_ps(_mm_mul_ps(_mm_loadu_ps(m), v0), _mm_mul_ps(_mm_loadu_ps(m + 3), v1)),
                                _mm_mul_ps(_mm_loadu_ps(m + 6), v2));
    _mm_store_ps(yj, _mm_add_ps(_mm_load_ps(yj), _mm_and_ps(t, mask)));
  }
}

// Flushes float results below the normal range (~1e-38) to 0 while it
// lives, the caller's mode restored after: far from the grips the sweeps'
// values fall through the float range geometrically, and each subnormal
// operand took the slow microcoded path (the passes ran 2x slower than the
// double ones).
class FlushSubnormals {
 public:
  FlushSubnormals() : saved_(_mm_getcsr()) { _mm_setcsr(saved_ | 0x8040u); }  // FTZ | DAZ
  ~FlushSubnormals() { _mm_setcsr(saved_); }
  FlushSubnormals(const FlushSubnormals&) = delete;
  FlushSubnormals& operator=(const FlushSubnormals&) = delete;

 private:
  unsigned saved_;
};

}  // namespace

void VertexBlockMatrix::sweep_from_zero_with_residual(const float* b, float* x, float* r) const {
  REPOSE_DEMAND(x != r && values_.size() >= value_count() + 4);
  const FlushSubnormals flush;
  // x needs no clearing: each x_i is stored (4 lanes) before a later row reads it
  std::fill(r, r + float_vector_size(), 0.0f);
  const int rows = block_rows();
  const float* values = values_.data();
  const int* column = column_.data();
  const float* scalars = values + source_.size();
  const int* scalar_column = identity_column_.data();
  for (int i = 0; i < rows; ++i) {
    const std::size_t u = static_cast<std::size_t>(i);
    const int begin = outer_[u], diagonal = diagonal_[u];
    const int scalar_begin = identity_outer_[u], scalar_upper = identity_upper_[u];
    const __m128 lower = _mm_add_ps(gather_blocks<false>(values, column, begin, diagonal, x),
                                    gather_scalars<false>(scalars, scalar_column, scalar_begin, scalar_upper, x));
    const __m128 s = _mm_sub_ps(_mm_load_ps(b + 4 * i), lower);
    const __m128 xi = times_inverse(&inverse_columns_[12 * u], s);
    _mm_store_ps(x + 4 * i, xi);
    // row j < i's residual -sum_{k > j} A_jk x_k takes -A_ji x_i = -A_ij^T x_i
    const __m128 minus_xi = _mm_sub_ps(_mm_setzero_ps(), xi);
    scatter_transposed(values, column, begin, diagonal, minus_xi, r);
    scatter_scalars(scalars, scalar_column, scalar_begin, scalar_upper, minus_xi, r);
  }
}

void VertexBlockMatrix::backward_sweep_with_product(const float* b, float* x, float* ax) const {
  REPOSE_DEMAND(x != ax && b != ax && values_.size() >= value_count() + 4);
  const FlushSubnormals flush;
  const int rows = block_rows();
  if (ax) std::copy(b, b + float_vector_size(), ax);
  const float* values = values_.data();
  const int* column = column_.data();
  const float* scalars = values + source_.size();
  const int* scalar_column = identity_column_.data();
  for (int i = rows - 1; i >= 0; --i) {
    const std::size_t u = static_cast<std::size_t>(i);
    const int diagonal = diagonal_[u], begin = outer_[u], end = outer_[u + 1];
    const int scalar_begin = identity_outer_[u], scalar_upper = identity_upper_[u], scalar_end = identity_outer_[u + 1];
    const __m128 upper = gather_blocks<true>(values, column, diagonal + 1, end, x);
    const __m128 lower = gather_blocks<true>(values, column, begin, diagonal, x);
    // the row's scalar blocks, both sides, in one backward run
    const __m128 scalar = gather_scalars<true>(scalars, scalar_column, scalar_begin, scalar_end, x);
    const __m128 s = _mm_sub_ps(_mm_load_ps(b + 4 * i), _mm_add_ps(_mm_add_ps(upper, lower), scalar));
    const __m128 xi = times_inverse(&inverse_columns_[12 * u], s);
    const __m128 change = _mm_sub_ps(xi, _mm_load_ps(x + 4 * i));
    _mm_store_ps(x + 4 * i, xi);
    // rows k > i (not yet final in ax) take A_ki (x_i - x_i before) = A_ik^T change
    if (ax) {
      scatter_transposed(values, column, diagonal + 1, end, change, ax);
      scatter_scalars(scalars, scalar_column, scalar_upper, scalar_end, change, ax);
    }
  }
}

}  // namespace repose
