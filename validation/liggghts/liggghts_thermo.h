#pragma once
// The thermo table of a LIGGGHTS log: the blocks that start with a header
// line "Step ..." and continue with numeric rows, joined into one table.
// A block with a different header (a new thermo_style) starts the table
// over, so the table holds the last style's blocks; a step repeated at the
// start of the next run block is kept once.

#include <string>
#include <vector>

namespace repose {

struct ThermoTable {
  std::vector<std::string> columns;       // as in the header, e.g. Step Atoms KinEng obj0[1]
  std::vector<std::vector<double>> rows;  // one per thermo line, in step order

  // Index of a column, or -1.
  int column(const std::string& name) const;
};

// Throws InputError naming the log when it cannot be read or holds no thermo lines.
ThermoTable read_thermo_table(const std::string& log_path);

}  // namespace repose
