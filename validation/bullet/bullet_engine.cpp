#include "validation/bullet/bullet_engine.h"

#include "validation/bullet/bullet_debris_world.h"
#include "validation/bullet/bullet_world.h"

namespace repose {

RigidEngine bullet_engine(const BulletOptions& options) {
  validate(options);
  RigidEngine engine;
  engine.name = "bullet";
  engine.version = bullet_version();
  engine.options_text = bullet_options_text(options);
  engine.rigid = options.rigid;
  engine.make_world = [options](const RigidWorldSpec& spec) { return make_bullet_world(spec, options); };
  engine.make_debris_world = [options](const DebrisWorldSpec& spec) { return make_bullet_debris_world(spec, options); };
  return engine;
}

}  // namespace repose
