#pragma once
// A seeded Halton sequence: low-discrepancy points in [0, 1)^d that spread
// the starts of a fit evenly over its bounds. Dimension k uses the k-th prime
// as its base (radical inverse of the index); the seed shifts every
// dimension by its own offset drawn from std::mt19937_64(seed), modulo 1 (a
// Cranley-Patterson rotation), so different seeds give different, equally
// even point sets and the same seed the same points on every run.

#include <cstdint>
#include <vector>

namespace repose {

class Halton {
 public:
  // dimension in [1, 32].
  Halton(int dimension, std::uint64_t seed);

  // The index-th point (index >= 1; index 0 of the plain sequence is the
  // corner 0, so it is left out).
  std::vector<double> point(std::uint64_t index) const;
  int dimension() const { return static_cast<int>(shift_.size()); }

 private:
  std::vector<double> shift_;
};

// The radical inverse of index in base (>= 2): its digits mirrored about the point.
double radical_inverse(std::uint64_t index, int base);

}  // namespace repose
