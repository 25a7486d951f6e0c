#pragma once
// What a solver returns: a typed run. The fields it produced (height fields
// and other grids on the scene's grid), named scalar measures with units,
// quantities over time (time_series.h),
// the modules it built, its timings and the files it wrote. The command
// line, the experiment runner and calibration read runs, never JSON text.

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "models/core/geometry/height_field.h"
#include "models/core/solver/time_series.h"

namespace repose {

struct Measure {
  double value = 0.0;
  std::string unit;  // "m", "m^3", "s", "kg", "rad", "1" (dimensionless), "count"

  bool operator==(const Measure&) const = default;
};

struct Run {
  std::string solver;
  // Gridded fields by name: "height_initial" and "height_final" (m) for
  // every solver that has a ground; others as each solver documents.
  std::map<std::string, HeightField> fields;
  // Scalars by dotted name ("steps", "volume.imbalance_m3", "mass_held_kg.ball").
  std::map<std::string, Measure> measures;
  // Quantities over the run by dotted name ("mass_held_kg.bucket"), as
  // each solver documents; like fields, not written into the manifest.
  std::map<std::string, TimeSeries> series;
  // Text and structured results that are not measures (versions, hashes);
  // written into the manifest's results beside the measures.
  nlohmann::json details = nlohmann::json::object();
  std::vector<std::string> stages;  // the modules the scene built, e.g. "collision:cpu", "erosion"
  double wall_s = 0.0;              // the solver's own run, without writing files
  double cpu_s = 0.0;
  std::vector<std::string> files;   // written into the run folder, relative to it

  // The field, or InputError naming the solver and the fields it has.
  const HeightField& field(const std::string& name) const;
  // The measure, or InputError naming the solver and the measures it has.
  const Measure& measure(const std::string& name) const;
  void set(const std::string& name, double value, const std::string& unit) { measures[name] = Measure{value, unit}; }
};

// Manifest "results": the measures as nested objects by their dotted names
// ({"volume": {"imbalance_m3": ...}}), merged with details.
nlohmann::json results_json(const Run& run);

// The run without its fields: solver, measures (value and unit), details,
// stages, timings and files. from_json reads it back.
void to_json(nlohmann::json& json, const Run& run);
void from_json(const nlohmann::json& json, Run& run);

}  // namespace repose
