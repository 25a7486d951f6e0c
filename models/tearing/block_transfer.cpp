#include "models/tearing/block_transfer.h"

#include <algorithm>
#include <utility>

#include "models/core/base/error.h"

namespace repose {

BlockTransfer::BlockTransfer(const Eigen::SparseMatrix<double>& p)
    : coarse_rows_(static_cast<int>(p.cols() / 3)) {
  REPOSE_DEMAND(p.rows() % 3 == 0 && p.cols() % 3 == 0);
  const int fine_rows = static_cast<int>(p.rows() / 3);
  // per fine vertex its (coarse vertex, axis, weight), then sorted by coarse vertex
  std::vector<std::vector<std::pair<int, std::pair<int, double>>>> links(static_cast<std::size_t>(fine_rows));
  for (int c = 0; c < p.outerSize(); ++c) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(p, c); it; ++it) {
      REPOSE_DEMAND(it.row() % 3 == c % 3);  // the axis kept
      links[static_cast<std::size_t>(it.row() / 3)].push_back({c / 3, {c % 3, it.value()}});
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
}

template <int kStride, typename Scalar>
void BlockTransfer::restrict_strided(const Scalar* fine, Eigen::VectorXd* coarse) const {
  coarse->setZero(3 * static_cast<Eigen::Index>(coarse_rows_));
  double* out = coarse->data();
  const int rows = fine_rows();
  for (int i = 0; i < rows; ++i, fine += kStride) {
    const double f0 = fine[0], f1 = fine[1], f2 = fine[2];
    for (int k = outer_[static_cast<std::size_t>(i)]; k < outer_[static_cast<std::size_t>(i) + 1]; ++k) {
      const double* w = weight_.data() + 3 * static_cast<std::ptrdiff_t>(k);
      double* c = out + 3 * static_cast<std::ptrdiff_t>(coarse_[static_cast<std::size_t>(k)]);
      c[0] += w[0] * f0;
      c[1] += w[1] * f1;
      c[2] += w[2] * f2;
    }
  }
}

void BlockTransfer::restrict_to(const Eigen::VectorXd& fine, Eigen::VectorXd* coarse) const {
  REPOSE_DEMAND(fine.size() == 3 * static_cast<Eigen::Index>(fine_rows()) && coarse != &fine);
  restrict_strided<3>(fine.data(), coarse);
}

void BlockTransfer::restrict_to(const float* fine, Eigen::VectorXd* coarse) const {
  restrict_strided<4>(fine, coarse);
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

void BlockTransfer::add_interpolated(const Eigen::VectorXd& coarse, float* fine) const {
  REPOSE_DEMAND(coarse.size() == 3 * static_cast<Eigen::Index>(coarse_rows_));
  const double* in = coarse.data();
  const int rows = fine_rows();
  for (int i = 0; i < rows; ++i, fine += 4) {
    double s0 = 0.0, s1 = 0.0, s2 = 0.0;
    for (int k = outer_[static_cast<std::size_t>(i)]; k < outer_[static_cast<std::size_t>(i) + 1]; ++k) {
      const double* w = weight_.data() + 3 * static_cast<std::ptrdiff_t>(k);
      const double* c = in + 3 * static_cast<std::ptrdiff_t>(coarse_[static_cast<std::size_t>(k)]);
      s0 += w[0] * c[0];
      s1 += w[1] * c[1];
      s2 += w[2] * c[2];
    }
    fine[0] += static_cast<float>(s0);
    fine[1] += static_cast<float>(s1);
    fine[2] += static_cast<float>(s2);
  }
}

}  // namespace repose
