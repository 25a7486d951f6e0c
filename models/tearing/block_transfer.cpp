#include "models/tearing/block_transfer.h"

#include <algorithm>
#include <utility>

#include <emmintrin.h>

#include "models/core/base/error.h"

namespace repose {

namespace {

std::vector<int> identity_places(Eigen::Index count) {
  std::vector<int> place(static_cast<std::size_t>(count));
  for (std::size_t k = 0; k < place.size(); ++k) place[k] = static_cast<int>(k);
  return place;
}

}  // namespace

BlockTransfer::BlockTransfer(const Eigen::SparseMatrix<double>& p)
    : BlockTransfer(p, identity_places(p.rows()), identity_places(p.cols()), static_cast<int>(p.rows() / 3),
                    static_cast<int>(p.cols() / 3)) {
  REPOSE_DEMAND(p.rows() % 3 == 0 && p.cols() % 3 == 0);
}

BlockTransfer::BlockTransfer(const Eigen::SparseMatrix<double>& p, const std::vector<int>& fine_place,
                             const std::vector<int>& coarse_place, int fine_rows, int coarse_rows)
    : coarse_rows_(coarse_rows) {
  REPOSE_DEMAND(fine_place.size() == static_cast<std::size_t>(p.rows()) &&
                coarse_place.size() == static_cast<std::size_t>(p.cols()));
  // per fine vertex its (coarse vertex, axis, weight), then sorted by coarse vertex
  std::vector<std::vector<std::pair<int, std::pair<int, double>>>> links(static_cast<std::size_t>(fine_rows));
  for (int col = 0; col < p.outerSize(); ++col) {
    const int c = coarse_place[static_cast<std::size_t>(col)];
    REPOSE_DEMAND(c >= 0 && c < 3 * coarse_rows);
    for (Eigen::SparseMatrix<double>::InnerIterator it(p, col); it; ++it) {
      const int r = fine_place[static_cast<std::size_t>(it.row())];
      REPOSE_DEMAND(r >= 0 && r < 3 * fine_rows && r % 3 == c % 3);  // the axis kept
      links[static_cast<std::size_t>(r / 3)].push_back({c / 3, {c % 3, it.value()}});
    }
  }
  outer_.assign(1, 0);
  for (auto& row : links) {
    std::stable_sort(row.begin(), row.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    for (const auto& [coarse, entry] : row) {
      if (coarse_.size() == static_cast<std::size_t>(outer_.back()) || coarse_.back() != coarse) {
        coarse_.push_back(coarse);
        weight_.insert(weight_.end(), {0.0, 0.0, 0.0});
      }
      weight_[weight_.size() - 3 + static_cast<std::size_t>(entry.first)] = entry.second;
    }
    outer_.push_back(static_cast<int>(coarse_.size()));
  }
  // per coarse vertex its links, fine vertices ascending (counting sort)
  reverse_outer_.assign(static_cast<std::size_t>(coarse_rows_) + 1, 0);
  for (const int c : coarse_) ++reverse_outer_[static_cast<std::size_t>(c) + 1];
  for (int c = 0; c < coarse_rows_; ++c) reverse_outer_[static_cast<std::size_t>(c) + 1] += reverse_outer_[static_cast<std::size_t>(c)];
  std::vector<int> at(reverse_outer_.begin(), reverse_outer_.end() - 1);
  fine_.resize(coarse_.size());
  reverse_weight_.resize(weight_.size());
  for (int i = 0; i < fine_rows; ++i) {
    for (int k = outer_[static_cast<std::size_t>(i)]; k < outer_[static_cast<std::size_t>(i) + 1]; ++k) {
      const int slot = at[static_cast<std::size_t>(coarse_[static_cast<std::size_t>(k)])]++;
      fine_[static_cast<std::size_t>(slot)] = i;
      std::copy_n(weight_.begin() + 3 * k, 3, reverse_weight_.begin() + 3 * slot);
    }
  }
}

// Per coarse vertex, its fine vertices' entries times their weights summed
// from 0 in ascending fine order: the order in which Eigen's product with
// P^T (column-major: fine entries in turn, scattered) adds them.
void BlockTransfer::restrict_doubles(const double* fine, Eigen::VectorXd* coarse) const {
  coarse->resize(3 * static_cast<Eigen::Index>(coarse_rows_));
  double* out = coarse->data();
  for (int c = 0; c < coarse_rows_; ++c, out += 3) {
    double s0 = 0.0, s1 = 0.0, s2 = 0.0;
    for (int k = reverse_outer_[static_cast<std::size_t>(c)]; k < reverse_outer_[static_cast<std::size_t>(c) + 1]; ++k) {
      const double* w = reverse_weight_.data() + 3 * static_cast<std::ptrdiff_t>(k);
      const double* f = fine + 3 * static_cast<std::ptrdiff_t>(fine_[static_cast<std::size_t>(k)]);
      s0 += w[0] * f[0];
      s1 += w[1] * f[1];
      s2 += w[2] * f[2];
    }
    out[0] = s0;
    out[1] = s1;
    out[2] = s2;
  }
}

void BlockTransfer::restrict_to(const Eigen::VectorXd& fine, Eigen::VectorXd* coarse) const {
  REPOSE_DEMAND(fine.size() == 3 * static_cast<Eigen::Index>(fine_rows()) && coarse != &fine);
  restrict_doubles(fine.data(), coarse);
}

// The same from float vectors, axes 0 and 1 two doubles at a time (SSE2,
// part of every x86-64: the same double products and sums per lane).
void BlockTransfer::restrict_to(const float* fine, Eigen::VectorXd* coarse) const {
  coarse->resize(3 * static_cast<Eigen::Index>(coarse_rows_));
  double* out = coarse->data();
  for (int c = 0; c < coarse_rows_; ++c, out += 3) {
    __m128d s01 = _mm_setzero_pd();
    double s2 = 0.0;
    for (int k = reverse_outer_[static_cast<std::size_t>(c)]; k < reverse_outer_[static_cast<std::size_t>(c) + 1]; ++k) {
      const double* w = reverse_weight_.data() + 3 * static_cast<std::ptrdiff_t>(k);
      const float* f = fine + 4 * static_cast<std::ptrdiff_t>(fine_[static_cast<std::size_t>(k)]);
      s01 = _mm_add_pd(s01, _mm_mul_pd(_mm_loadu_pd(w), _mm_cvtps_pd(_mm_loadu_ps(f))));
      s2 += w[2] * f[2];
    }
    _mm_storeu_pd(out, s01);
    out[2] = s2;
  }
}

void BlockTransfer::add_interpolated(const Eigen::VectorXd& coarse, Eigen::VectorXd* fine) const {
  REPOSE_DEMAND(coarse.size() == 3 * static_cast<Eigen::Index>(coarse_rows_) &&
                fine->size() == 3 * static_cast<Eigen::Index>(fine_rows()) && fine != &coarse);
  const double* in = coarse.data();
  double* out = fine->data();
  const int rows = fine_rows();
  for (int i = 0; i < rows; ++i, out += 3) {
    for (int k = outer_[static_cast<std::size_t>(i)]; k < outer_[static_cast<std::size_t>(i) + 1]; ++k) {
      const double* w = weight_.data() + 3 * static_cast<std::ptrdiff_t>(k);
      const double* c = in + 3 * static_cast<std::ptrdiff_t>(coarse_[static_cast<std::size_t>(k)]);
      out[0] += w[0] * c[0];
      out[1] += w[1] * c[1];
      out[2] += w[2] * c[2];
    }
  }
}

// Axes 0 and 1 two doubles at a time (SSE2), as restrict_to's.
void BlockTransfer::add_interpolated(const Eigen::VectorXd& coarse, float* fine) const {
  REPOSE_DEMAND(coarse.size() == 3 * static_cast<Eigen::Index>(coarse_rows_));
  const double* in = coarse.data();
  const int rows = fine_rows();
  for (int i = 0; i < rows; ++i, fine += 4) {
    __m128d s01 = _mm_setzero_pd();
    double s2 = 0.0;
    for (int k = outer_[static_cast<std::size_t>(i)]; k < outer_[static_cast<std::size_t>(i) + 1]; ++k) {
      const double* w = weight_.data() + 3 * static_cast<std::ptrdiff_t>(k);
      const double* c = in + 3 * static_cast<std::ptrdiff_t>(coarse_[static_cast<std::size_t>(k)]);
      s01 = _mm_add_pd(s01, _mm_mul_pd(_mm_loadu_pd(w), _mm_loadu_pd(c)));
      s2 += w[2] * c[2];
    }
    alignas(16) double s[2];
    _mm_store_pd(s, s01);
    fine[0] += static_cast<float>(s[0]);
    fine[1] += static_cast<float>(s[1]);
    fine[2] += static_cast<float>(s2);
  }
}

}  // namespace repose
