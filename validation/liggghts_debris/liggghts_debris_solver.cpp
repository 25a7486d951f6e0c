#include "validation/liggghts_debris/liggghts_debris_solver.h"

#include <filesystem>
#include <unistd.h>

#include <fmt/format.h>

#include "models/core/config/scene.h"
#include "models/terrain/terrain_section.h"
#include "validation/liggghts_debris/liggghts_debris_run.h"
#include "validation/liggghts_debris/liggghts_debris_script.h"
#include "validation/particles/dem_section.h"
#include "validation/rigid/debris_solver.h"

namespace repose {

namespace {

namespace fs = std::filesystem;

class CompiledLiggghtsDebris final : public CompiledSolver {
 public:
  explicit CompiledLiggghtsDebris(const Scene& scene)
      : terrain_(terrain_section(scene).scene), grid_(scene.ground.grid), duration_s_(scene.time.duration_s) {
    if (!terrain_.elements) throw InputError("terrain: elements: a debris run needs moving elements (terrain: elements)");
    terrain_.validate();
    options_.validate();
  }
  const std::vector<ParameterInfo>& parameters() const override { return parameters_; }

  Run run(const std::vector<double>& values_si, const RunOptions& options) const override {
    check_values(parameters_, values_si, "liggghts");
    HeightField initial;
    const DebrisSetup setup = solver_debris_setup(terrain_, grid_, DebrisMaterial{}, 1.0, &initial);
    const bool temporary = options.output_dir.empty();
    const fs::path dir = temporary ? fs::temp_directory_path() / fmt::format("repose-liggghts-debris-{}", ::getpid())
                                   : fs::path(options.output_dir);
    LiggghtsRunOptions run_options;
    run_options.progress = options.progress;
    const LiggghtsDebrisResult r = run_liggghts_debris(setup, duration_s_, options_, dir.string(), run_options);
    Run run = debris_run_record(r.run, setup, initial, options_.time_step_s, "liggghts");
    run.stages = {"terrain", "liggghts-debris"};
    run.details["engine_version"] = r.version;
    if (temporary) {
      fs::remove_all(dir);
      return run;
    }
    run.files = write_debris_run(r.run, setup, dir.string());
    for (const char* f : {kDebrisScriptFile, kDebrisDataFile, "log.liggghts"}) run.files.emplace_back(f);
    const LiggghtsDebrisScript script = liggghts_debris_script(setup, duration_s_, options_);
    for (const DebrisMeshFile& m : script.meshes) run.files.push_back(m.file_name);
    if (!setup.building_names.empty()) run.files.emplace_back(kDebrisForceFile);
    return run;
  }

 private:
  TerrainScene terrain_;
  Grid grid_;
  double duration_s_;
  LiggghtsDebrisOptions options_;
  std::vector<ParameterInfo> parameters_;
};

}  // namespace

std::string LiggghtsDebrisSolver::description() const {
  return dem_.description() + "; or a terrain section's debris flow (terrain a mesh wall, buildings fixed meshes)";
}

std::vector<SectionType> LiggghtsDebrisSolver::sections() const {
  std::vector<SectionType> out = dem_.sections();
  out.push_back(terrain_section_type());
  return out;
}

bool LiggghtsDebrisSolver::can_run(const Scene& scene, std::string* why) const {
  if (dem_of(scene) != nullptr) return dem_.can_run(scene, why);
  if (scene.section<TerrainSection>() != nullptr) return true;
  if (why != nullptr) *why = "the scene has neither a 'dem' section (grains) nor a 'terrain' section (a debris flow)";
  return false;
}

std::unique_ptr<CompiledSolver> LiggghtsDebrisSolver::compile(const Scene& scene) const {
  if (dem_of(scene) != nullptr || scene.section<TerrainSection>() == nullptr) return dem_.compile(scene);
  return std::make_unique<CompiledLiggghtsDebris>(scene);
}

}  // namespace repose
