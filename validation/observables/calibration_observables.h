#pragma once
// The observables of a calibration (calibration_spec.h, ObservableSpec) taken
// from a run's initial and final surfaces, the same way for the heuristic and
// the reference, so that they can be subtracted value by value.

#include <map>
#include <string>
#include <vector>

#include "models/core/geometry/height_field.h"
#include "models/core/solver/time_series.h"
#include "validation/observables/observable_spec.h"

namespace repose {

// A run's time series by name (Run::series).
using SeriesByName = std::map<std::string, TimeSeries>;
// A run's scalar measures by dotted name, in their SI units (Run::measures).
using MeasureByName = std::map<std::string, double>;

// The values of one observable (SI units, radians): the cells of a region
// (row-major), the samples of a transect, one scalar, or a series at its
// times (TimeSeries::at), or a measure. Throws InputError when a region holds
// no cell centre of the grid, or for a series or measure the run does not have
// (naming those it has).
std::vector<double> observe(const ObservableSpec& observable, const HeightField& initial, const HeightField& final_height,
                            const SeriesByName& series = {}, const MeasureByName& measures = {});

// Indices (row-major) of the cells whose centre lies in region (all cells without one).
std::vector<std::size_t> cells_in(const std::optional<CalibrationRegion>& region, const Grid& grid);

// Root-mean-square difference of two fields on the same grid over the cells of region.
double surface_rmse_m(const HeightField& a, const HeightField& b, const std::optional<CalibrationRegion>& region);

}  // namespace repose
