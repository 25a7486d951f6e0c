#pragma once
// A rigid-body engine as the shared reference code sees it: its name and
// version (for manifests and cache keys), its options as text, and how it
// builds a world. validation/bullet and validation/ode each make one.

#include <string>

#include "validation/rigid/debris_world.h"
#include "validation/rigid/rigid_options.h"
#include "validation/rigid/rigid_world.h"

namespace repose {

struct RigidEngine {
  std::string name;          // "bullet", "ode": the scene section and solver name
  std::string version;       // e.g. "Bullet 3.24 (double)": enters cache keys and manifests
  std::string options_text;  // every option of the engine's section, key=value lines (enters cache keys)
  RigidOptions rigid;        // the shared part of the options
  RigidWorldFactory make_world;
  DebrisWorldFactory make_debris_world;  // a terrain scene's debris flow (debris_world.h)
};

}  // namespace repose
