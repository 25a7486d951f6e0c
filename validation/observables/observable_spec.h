#pragma once
// What is compared between a solver's run and a reference's: one measured
// quantity of a run's final surface, or of a quantity over the run at given
// times (SI units, radians).

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace repose {

// An axis-aligned rectangle of the ground (m); cells whose centre lies inside
// (edges included) belong to it.
struct CalibrationRegion {
  double x_min_m = 0.0, x_max_m = 0.0, y_min_m = 0.0, y_max_m = 0.0;
  bool contains(double x_m, double y_m) const {
    return x_m >= x_min_m && x_m <= x_max_m && y_m >= y_min_m && y_m <= y_max_m;
  }
};

// One measured quantity of a run's final surface. Residuals are
// weight * (heuristic - reference) / sqrt(count) for an observable of count
// values, so a field of many cells and a single scalar weigh alike at equal
// weights, and the squared residuals of a field sum to weight^2 * its MSE.
struct ObservableSpec {
  enum class Kind {
    kHeightField,  // final heights (m) of the cells in region
    kTransect,     // final heights (m) sampled (bilinear) at `samples` points from from_m to to_m
    kCraterDepth,  // mean initial height in region minus the lowest final height there (m)
    kRimHeight,    // highest final height in region minus the mean initial height there (m)
    kPileAngle,    // mean flank angle (rad) of the final surface around centre_m (0 without a flank)
    kFurrowArea,   // cross-section (m^2) below the initial surface along from_m..to_m
    kSeries,       // a run's time series (Run::series, time_series.h) `series` at each of times_s
    kMeasure,      // a run's scalar measure (Run::measures) `measure`, in its SI unit
    kHeapFlank,    // flank angle (rad) of the heap peaking in region (heap_flank.h), above base_height_m
  };
  Kind kind = Kind::kHeightField;
  double weight = 1.0;  // > 0; residuals are in SI units times this
  std::optional<CalibrationRegion> region;  // height_field, crater_depth, rim_height (default: whole grid)
  Eigen::Vector2d from_m = Eigen::Vector2d::Zero();  // transect, furrow_area
  Eigen::Vector2d to_m = Eigen::Vector2d::Zero();
  int samples = 32;                                  // transect, furrow_area: points along the line (>= 2)
  Eigen::Vector2d centre_m = Eigen::Vector2d::Zero();  // pile_angle
  // series: its name ("mass_held_kg.bucket": the mass an object holds, which
  // a particle reference reads from its held_mass.csv) and the times (s) it
  // is compared at, >= 1, increasing
  std::string series;
  std::vector<double> times_s;
  // measure: its dotted name ("chute.peak.force_n"); a particle reference
  // reads it from its manifest's results
  std::string measure;
  // heap_flank: heights are taken above base_height_m (default: the initial
  // surface's mean height over the grid) and the rays reach reach_m from the
  // peak (heap_flank.h, HeapFlankOptions); a data reference with several
  // seeds is the mean of each seed's flank, as for series and measures
  std::optional<double> base_height_m;
  double reach_m = 0.1;
};

const char* observable_kind_name(ObservableSpec::Kind kind);

}  // namespace repose
