#pragma once
// Where the ground's material went (m^3): what a run starts with equals what
// it ends with plus what was compressed away plus what left the grid.
// Bedrock (below the base, z = 0) is not material: it never moves, so it is
// outside the balance; bedrock_m3 says that, and how far, objects met it.

#include <cmath>

namespace repose {

struct VolumeLedger {
  double initial_m3 = 0.0;     // volume of the initial height field
  double compressed_m3 = 0.0;  // (1 - displaced fraction) * dh' summed over contacts
  double left_grid_m3 = 0.0;   // displaced past the grid's edge (open boundary of displacement)
  double bedrock_m3 = 0.0;     // largest volume below the base that one contact's underside reached (0: none)

  // initial - (final + compressed + left): zero to round-off.
  double imbalance_m3(double final_m3) const { return initial_m3 - (final_m3 + compressed_m3 + left_grid_m3); }
};

}  // namespace repose
