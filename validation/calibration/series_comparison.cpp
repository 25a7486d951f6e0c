#include "validation/calibration/series_comparison.h"

#include <limits>

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

std::vector<SeriesComparison> compare_series(const PreparedScene& scene, const Run& initial, const Run& fitted) {
  std::vector<SeriesComparison> out;
  for (std::size_t o = 0; o < scene.entry.observables.size(); ++o) {
    const ObservableSpec& spec = scene.entry.observables[o];
    if (spec.kind != ObservableSpec::Kind::kSeries) continue;
    SeriesComparison c;
    c.series = spec.series;
    const auto it = fitted.series.find(spec.series);
    if (it != fitted.series.end()) c.unit = it->second.unit;
    c.times_s = spec.times_s;
    for (const SeriesByName& seed : scene.seed_series) {
      c.seeds.push_back(observe(spec, scene.initial, scene.reference_final, seed));
    }
    c.reference = scene.reference_values[o];
    c.initial = observe(spec, scene.initial, initial.field("height_final"), initial.series);
    c.fitted = observe(spec, scene.initial, fitted.field("height_final"), fitted.series);
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace repose
