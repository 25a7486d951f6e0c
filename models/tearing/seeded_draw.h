#pragma once
// Uniform draws from a std::mt19937_64 passed in, written out rather than
// through std::uniform_real_distribution (whose algorithm the standard leaves
// to the library), so that a seed gives the same fibres on every platform.

#include <cstdint>
#include <random>

namespace repose {

// In [0, 1): the top 53 bits of one draw.
inline double draw_unit(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

// In [lo, hi); lo when hi == lo.
inline double draw_between(std::mt19937_64& rng, double lo, double hi) { return lo + (hi - lo) * draw_unit(rng); }

}  // namespace repose
