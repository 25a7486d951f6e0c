#pragma once
// What a reference run folder cost: read from its typed records, never by
// re-parsing text. A run folder of `repose run` holds manifest.json with its
// Run (models/core/solver/run.h); a LIGGGHTS run folder also holds
// liggghts_manifest.json (its run's wall and CPU time).

#include <map>
#include <optional>
#include <string>

namespace repose {

struct RunCost {
  double wall_s = 0.0;
  double cpu_s = 0.0;
};

// The folder's cost, or nothing when it holds no record of it. InputError for
// a record that is not valid JSON of the expected shape.
std::optional<RunCost> read_run_cost(const std::string& folder);

// The run's scalar measures (its manifest.json's Run), by dotted name, in
// their units; empty when the folder has no manifest.json. InputError for a
// manifest that is not valid JSON of the expected shape.
std::map<std::string, double> read_run_measures(const std::string& folder);

// The engine that made the run: "liggghts" for a folder with LIGGGHTS' own
// record, else the solver its manifest.json names. InputError when neither
// says.
std::string read_run_engine(const std::string& folder);

}  // namespace repose
