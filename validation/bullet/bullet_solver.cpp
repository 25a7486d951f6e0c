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

std::unique_ptr<CompiledSolver> BulletSolver::compile(const Scene& scene) const {
  return compile_rigid(scene, bullet_engine(bullet_options_of(scene)));
}

}  // namespace repose
