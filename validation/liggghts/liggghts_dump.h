#pragma once
// LIGGGHTS/LAMMPS `dump custom` text files:
//   ITEM: TIMESTEP / N / ITEM: NUMBER OF ATOMS / N / ITEM: BOX BOUNDS ff ff ff /
//   3 lines "lo hi" / ITEM: ATOMS id type x y z radius ... / N lines
// one or more such frames per file. Columns may come in any order; id, x, y,
// z and radius are required, type is optional (1 when absent), vx vy vz are
// read into the grains' velocities when all three are there, others are ignored.

#include <string>
#include <vector>

#include "validation/particles/grain_set.h"

namespace repose {

struct DumpFrame {
  long timestep = 0;
  double box_lo_m[3] = {0, 0, 0};
  double box_hi_m[3] = {0, 0, 0};
  std::vector<long> id;    // as in the file (sorted when dump_modify sort id was used)
  std::vector<int> type;
  GrainSet grains;         // positions and radii, in file order
};

// Every frame of the file. Throws InputError naming the file, the line and
// what is wrong: missing or unreadable, truncated, a count that disagrees
// with the rows, a non-numeric or non-finite value, a missing column, a
// negative or zero radius, a header out of order.
std::vector<DumpFrame> read_dump_file(const std::string& path);
// The last frame of the file (InputError when it holds none).
DumpFrame read_last_dump_frame(const std::string& path);

// The dump files of a directory ("dump.<step>.txt"), sorted by step.
std::vector<std::string> list_dump_files(const std::string& directory);

}  // namespace repose
