#include "validation/bullet/bullet_solver.h"

#include "validation/bullet/bullet_engine.h"
#include "validation/bullet/bullet_section.h"
#include "validation/particles/dem_section.h"
#include "validation/rigid/rigid_solver.h"

namespace repose {

std::string BulletSolver::description() const {
  return "rigid spheres in Bullet (needs the scene's dem section; options in bullet:): settled bed, run, observables";
}

std::vector<SectionType> BulletSolver::sections() const { return {dem_section_type(), bullet_section_type()}; }

bool BulletSolver::can_run(const Scene& scene, std::string* why) const {
  if (dem_of(scene) != nullptr) return true;
  if (why != nullptr) *why = "the scene has no 'dem' section (the grains of the particle references)";
  return false;
}

std::unique_ptr<CompiledSolver> BulletSolver::compile(const Scene& scene) const {
  return compile_rigid(scene, bullet_engine(bullet_options_of(scene)));
}

}  // namespace repose
