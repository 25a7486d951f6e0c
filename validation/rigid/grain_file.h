#pragma once
// Grains as one .npy array, #G by 4 (x y z r, m, float64): round-trip exact.

#include <string>

#include "validation/particles/grain_set.h"

namespace repose {

void write_grains_npy(const std::string& path, const GrainSet& grains);
// Throws InputError for an array that is not #G by 4.
GrainSet read_grains_npy(const std::string& path);

}  // namespace repose
