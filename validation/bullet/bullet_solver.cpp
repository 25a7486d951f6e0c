#include "validation/bullet/bullet_solver.h"

#include "validation/bullet/bullet_engine.h"
#include "validation/bullet/bullet_section.h"
#include "models/terrain/terrain_section.h"
#include "validation/particles/dem_section.h"
#include "validation/rigid/rigid_solver.h"

namespace repose {

std::string BulletSolver::description() const {
  return "rigid bodies in Bullet (options in bullet:): a dem section's grains (settled bed, run, observables) or a terrain section's debris flow with breakable buildings";
}

std::vector<SectionType> BulletSolver::sections() const { return {dem_section_type(), bullet_section_type(), terrain_section_type()}; }

bool BulletSolver::can_run(const Scene& scene, std::string* why) const {
  if (dem_of(scene) != nullptr || scene.section<TerrainSection>() != nullptr) return true;  // terrain: a debris flow
  if (why != nullptr) *why = "the scene has neither a 'dem' section (grains) nor a 'terrain' section (a debris flow)";
  return false;
}

std::unique_ptr<CompiledSolver> BulletSolver::compile(const Scene& scene) const {
  return compile_rigid(scene, bullet_engine(bullet_options_of(scene)));
}

}  // namespace repose
