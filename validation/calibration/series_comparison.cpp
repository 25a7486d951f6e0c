#include "validation/calibration/series_comparison.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "models/core/base/error.h"
#include "validation/observables/calibration_observables.h"

namespace repose {

std::vector<double> SeriesComparison::fitted_relative_error() const {
  std::vector<double> out;
  for (std::size_t k = 0; k < reference.size(); ++k) {
    const double d = fitted[k] - reference[k];
    out.push_back(reference[k] != 0.0 ? d / reference[k]
                  : d == 0.0          ? 0.0
                                      : std::numeric_limits<double>::infinity());
  }
  return out;
}

std::vector<double> SeriesComparison::paired_standard_error() const {
  const std::size_t beds = fitted_per_bed.size();
  if (beds < 2) return {};
  REPOSE_DEMAND(beds == seeds.size());
  std::vector<double> out;
  for (std::size_t k = 0; k < reference.size(); ++k) {
    if (reference[k] == 0.0) {
      out.push_back(std::numeric_limits<double>::quiet_NaN());
      continue;
    }
    double sum = 0.0, sum_squares = 0.0;
    for (std::size_t b = 0; b < beds; ++b) {
      const double paired = (fitted_per_bed[b][k] - seeds[b][k]) / reference[k];
      sum += paired;
      sum_squares += paired * paired;
    }
    const double mean = sum / beds;
    const double variance = std::max(0.0, (sum_squares - beds * mean * mean) / (beds - 1));
    out.push_back(std::sqrt(variance / beds));
  }
  return out;
}

std::vector<SeriesComparison> compare_series(const PreparedScene& scene, const std::vector<std::vector<double>>& initial,
                                             const std::vector<std::vector<double>>& fitted,
                                             const std::vector<std::vector<std::vector<double>>>& fitted_per_bed,
                                             const Run& fitted_run) {
  REPOSE_DEMAND(initial.size() == scene.entry.observables.size() && fitted.size() == initial.size() &&
                fitted_per_bed.size() == initial.size());
  using K = ObservableSpec::Kind;
  std::vector<SeriesComparison> out;
  for (std::size_t o = 0; o < scene.entry.observables.size(); ++o) {
    const ObservableSpec& spec = scene.entry.observables[o];
    if (!observed_per_seed(spec)) continue;
    SeriesComparison c;
    if (spec.kind == K::kHeapFlank) {
      c.series = "heap_flank";
      c.unit = "rad";
    } else if (spec.kind == K::kSeries) {
      c.series = spec.series;
      const auto it = fitted_run.series.find(spec.series);
      if (it != fitted_run.series.end()) c.unit = it->second.unit;
      c.times_s = spec.times_s;
    } else {
      c.series = spec.measure;
      const auto it = fitted_run.measures.find(spec.measure);
      if (it != fitted_run.measures.end()) c.unit = it->second.unit;
    }
    for (std::size_t seed = 0; seed < scene.seed_series.size(); ++seed) {
      c.seeds.push_back(seed_observation(spec, scene, seed));
    }
    c.reference = scene.reference_values[o];
    c.initial = initial[o];
    c.fitted = fitted[o];
    if (scene.bed_count() > 1) c.fitted_per_bed = fitted_per_bed[o];
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace repose
