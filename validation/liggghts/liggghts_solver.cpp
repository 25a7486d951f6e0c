#include "validation/liggghts/liggghts_solver.h"

#include <filesystem>
#include <unistd.h>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "validation/liggghts/liggghts_reference.h"
#include "validation/liggghts/liggghts_section.h"
#include "validation/liggghts/snowfall_reference.h"
#include "validation/liggghts/snowfall_script.h"
#include "validation/liggghts/snowfall_section.h"
#include "validation/particles/dem_section.h"

namespace repose {

namespace {

namespace fs = std::filesystem;

// Every number of the results as a measure (dotted names), the rest as details.
void split_results(const nlohmann::json& json, const std::string& prefix, Run& run) {
  for (const auto& [key, value] : json.items()) {
    const std::string name = prefix.empty() ? key : prefix + "." + key;
    if (value.is_object()) {
      split_results(value, name, run);
    } else if (value.is_number()) {
      const bool cost = name.ends_with("_s") && !name.ends_with("_m_s") && !name.starts_with("particle");
      run.set(name, value.get<double>(), cost ? "s" : name.starts_with("mass_held_kg") ? "kg" : "");
    } else {
      run.details[name] = value;
    }
  }
}

class CompiledLiggghts final : public CompiledSolver {
 public:
  explicit CompiledLiggghts(const Scene& scene) : scene_(scene) {}
  const std::vector<ParameterInfo>& parameters() const override { return parameters_; }

  Run run(const std::vector<double>& values_si, const RunOptions& options) const override {
    check_values(parameters_, values_si, "liggghts");
    LiggghtsReferenceOptions reference;
    reference.bed.run.progress = options.progress;
    reference.run.progress = options.progress;
    const bool temporary = options.output_dir.empty();
    const fs::path dir = temporary ? fs::temp_directory_path() / fmt::format("repose-liggghts-{}", ::getpid())
                                   : fs::path(options.output_dir);
    fs::create_directories(dir);
    if (dem_of(scene_)->initial == DemSpec::Initial::kSnowfall) {
      LiggghtsRunOptions snowfall = reference.run;
      Run run = run_liggghts_snowfall(scene_, dir.string(), snowfall);
      if (temporary) fs::remove_all(dir);
      if (!temporary) run.files = {"liggghts_manifest.json", "snowfall.in", "log.liggghts"};
      return run;
    }
    const LiggghtsReferenceResult r = run_liggghts_reference(scene_, dir.string(), reference);
    if (temporary) fs::remove_all(dir);

    Run run;
    run.solver = "liggghts";
    run.wall_s = r.run.wall_time_s;
    run.cpu_s = r.run.cpu_time_s;
    run.fields["height_initial"] = r.height_initial;
    run.fields["height_final"] = r.height_final;
    run.fields["material_per_area_final"] = r.material_per_area_final;
    run.stages = {r.bed.from_cache ? "bed:cached" : "bed:settled", "liggghts-run"};
    split_results(liggghts_results_json(r), "", run);
    if (!temporary) {
      run.files = {"height_final.csv", "height_initial.csv", "material_per_area_final.csv", "forces.csv",
                   "liggghts_manifest.json", "bed_manifest.json", "run.in", "log.liggghts"};
      for (const FreeBodyTrack& t : r.free_bodies) run.files.push_back("free_body_" + t.name + ".csv");
      if (r.column) run.files.push_back("runout.csv");
      if (r.pile) run.files.push_back("pile_flank_angles.csv");
      if (r.chute) run.files.push_back("chute_impact.csv");
    }
    return run;
  }

 private:
  Scene scene_;
  std::vector<ParameterInfo> parameters_;
};

}  // namespace

std::vector<SectionType> LiggghtsSolver::sections() const { return {dem_section_type(), liggghts_section_type(), snowfall_section_type()}; }

bool LiggghtsSolver::can_run(const Scene& scene, std::string* why) const {
  if (dem_of(scene) != nullptr) return true;
  if (why != nullptr) *why = "the scene has no 'dem' section (the grains of the particle references)";
  return false;
}

std::unique_ptr<CompiledSolver> LiggghtsSolver::compile(const Scene& scene) const {
  const DemSpec& dem = require_dem(scene, "LIGGGHTS");
  if (dem.initial == DemSpec::Initial::kSnowfall) {
    snowfall_script(scene);  // the snowfall's checks (snow section, flat ground, grain count) before any run
    return std::make_unique<CompiledLiggghts>(scene);
  }
  run_script(scene, RunScriptOptions{});  // the script's checks (objects, column geometry) before any run
  return std::make_unique<CompiledLiggghts>(scene);
}

}  // namespace repose
