#pragma once
// The tear-resistance check of the paper fit (issue 15, item 7): the ratio
// across / along the grain (CD / MD, as an Elmendorf tear test quotes it:
// a CD tear runs across the machine direction's fibres) of the energy the
// tear itself took, from the two directions' measured fracture energies,
// per seed and over the seeds, and its relative residual against a grade's
// published ratio.
//
// Two lengths per tear (tear_run.h): per unit depth (the projected length,
// tear.fracture_energy_per_length_j_per_m) and per unit length of the
// tortuous torn path (tear.fracture_energy_per_path_length_j_per_m).
// Elmendorf's tear is held to its slit, so its work is per projected
// length; the model's tear across the grain wanders between clumps, so
// per depth it counts cells an Elmendorf specimen would not tear. The check
// uses per path; the report shows both.

#include <map>
#include <string>
#include <vector>

namespace repose {

// Per seed, in the order of the fit file's tear_seeds: measure name ->
// value, for "md" (tear along the grain) and "cd" (across it).
using SeedMeasures = std::map<std::string, std::vector<std::map<std::string, double>>>;

struct TearRatio {
  std::vector<double> per_seed;  // CD / MD of each seed (same seed both ways)
  double mean = 0.0;             // CD mean / MD mean over the seeds
  double seed_sd = 0.0;          // sample standard deviation of per_seed (0 for one seed)
};

// measure: "tear.fracture_energy_per_path_length_j_per_m" or
// "tear.fracture_energy_per_length_j_per_m". Throws std::invalid_argument
// when the directions hold different numbers of seeds, none, or an MD
// energy that is not positive (the sheet did not tear along the grain).
TearRatio tear_ratio_cd_over_md(const SeedMeasures& tear, const std::string& measure);

// (model / published) - 1, as the fit's other residuals.
double tear_ratio_residual(const TearRatio& ratio, double published_cd_over_md);

}  // namespace repose
