#include "validation/ode/ode_engine.h"

#include "validation/ode/ode_debris_world.h"
#include "validation/ode/ode_world.h"

namespace repose {

RigidEngine ode_engine(const OdeOptions& options) {
  validate(options);
  RigidEngine engine;
  engine.name = "ode";
  engine.version = ode_version();
  engine.options_text = ode_options_text(options);
  engine.rigid = options.rigid;
  engine.make_world = [options](const RigidWorldSpec& spec) { return make_ode_world(spec, options); };
  engine.make_debris_world = [options](const DebrisWorldSpec& spec) { return make_ode_debris_world(spec, options); };
  return engine;
}

}  // namespace repose
