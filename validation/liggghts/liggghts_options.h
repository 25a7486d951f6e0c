#pragma once
// The liggghts: section of a scene: how LIGGGHTS finds contacts, which
// changes its speed, not its physics (as long as no neighbour build is
// "dangerous": a pair came within contact range between two list builds,
// which the run reports as neighbor.dangerous_builds). The defaults are
// the settings every canonical reference was run with. They apply to the
// run script only: the settled bed is made with the defaults, so tuning a
// run keeps its cached bed.
//
//   liggghts: {neighbor_skin_radii: 1.0, neighbor_check_every_steps: 1, sort_every_steps: 1000}

#include <string>

#include "models/core/config/fields.h"
#include "models/core/config/yaml_reader.h"

namespace repose {

struct LiggghtsOptions {
  // Neighbour-list skin (`neighbor SKIN bin`) in radii of the largest grain:
  // a wider skin rebuilds the list less often but holds more pairs.
  double neighbor_skin_radii = 1.0;
  // The list is checked for a rebuild every this many steps
  // (`neigh_modify every N check yes`); 1 checks every step.
  int neighbor_check_every_steps = 1;
  // Atoms re-ordered in memory by spatial bin every this many steps
  // (`atom_modify sort N 0`, cache locality); 0 never. LIGGGHTS' default.
  int sort_every_steps = 1000;
};

template <class V, class O>
void liggghts_option_fields(V& v, O& o) {
  v.number("neighbor_skin_radii", o.neighbor_skin_radii, Range::closed(0.05, 10.0));
  v.integer("neighbor_check_every_steps", o.neighbor_check_every_steps, IntRange{1, 1000});
  v.integer("sort_every_steps", o.sort_every_steps, IntRange{0, 1000000});
}

// Throws FieldError (an InputError) "KEY: expected RULE, got VALUE".
void validate(const LiggghtsOptions& options);

}  // namespace repose
