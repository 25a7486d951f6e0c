#include "validation/calibration/halton.h"

#include <cmath>
#include <random>

#include "models/core/base/error.h"

namespace repose {

namespace {

constexpr int kPrimes[] = {2,  3,  5,  7,  11, 13, 17, 19, 23, 29, 31, 37, 41,  43,  47,  53,
                           59, 61, 67, 71, 73, 79, 83, 89, 97, 101, 103, 107, 109, 113, 127, 131};

}  // namespace

double radical_inverse(std::uint64_t index, int base) {
  REPOSE_DEMAND(base >= 2);
  const double inverse_base = 1.0 / base;
  double scale = inverse_base, value = 0.0;
  while (index > 0) {
    value += static_cast<double>(index % static_cast<std::uint64_t>(base)) * scale;
    index /= static_cast<std::uint64_t>(base);
    scale *= inverse_base;
  }
  return value;
}

Halton::Halton(int dimension, std::uint64_t seed) {
  REPOSE_DEMAND(dimension >= 1 && dimension <= static_cast<int>(std::size(kPrimes)));
  std::mt19937_64 generator(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (int k = 0; k < dimension; ++k) shift_.push_back(uniform(generator));
}

std::vector<double> Halton::point(std::uint64_t index) const {
  REPOSE_DEMAND(index >= 1);
  std::vector<double> p(shift_.size());
  for (std::size_t k = 0; k < shift_.size(); ++k) {
    const double u = radical_inverse(index, kPrimes[k]) + shift_[k];
    p[k] = u - std::floor(u);
  }
  return p;
}

}  // namespace repose
