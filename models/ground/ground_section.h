#pragma once
// The ground model's section of a scene (`ground_model:`): its options (not
// fitted) and what each named material is made of. Materials the scene names
// (ground.material, ground.regions[].material) are either defined here or
// one of the presets (sand, mud, snow; material.h):
//
//   ground_model:
//     sweep: true                  # sweep translating objects between frames
//     substeps: 1                  # substeps per frame when not sweeping
//     max_substep_angle_deg: 5     # rotation per substep for rotating objects
//     erosion_memory_steps: 30     # steps an eroded cell keeps eroding
//     coarse_factor: 2             # coarsening for 'simple' or far objects
//     far_distance_m: 0            # objects farther than this from the camera use the coarse grid (0: never)
//     collision: cpu               # cpu | osmesa
//     bed_slope_deg: 0             # the bed inclined down +x (a bed-aligned chute; erosion.h)
//     heap_laying: portions        # portions | one_pass: how displaced material heaps on open ground (excess_routing.h)
//     materials:                   # optional: name -> {preset, alpha, repose_angle_deg, sigma, erosion_iterations, erosion_iterations_cell_m}
//       sand: {alpha: 0.9}         # a preset's name: its values, overridden
//       clay: {preset: mud, sigma: 0.1}
//       rock: {alpha: 0.1, repose_angle_deg: 80, sigma: 0.2}   # no preset: alpha, angle and sigma all given
//     free_bodies: {ode_step_s: 0.0016667, friction: 0.5}     # how ODE drives dynamic: objects (free_body_spec.h)
//     bearing: {law: bekker, exponent_n: 1.1}                # the ground's bearing rule for them (bekker_bearing.h)
//
// The section is read for every scene, present or not (its defaults), so that
// every material a scene names is checked when it is loaded.

#include <map>
#include <string>

#include "models/core/config/scene.h"
#include "models/core/config/scene_section.h"
#include "models/core/config/yaml_reader.h"
#include "models/ground/free_body_spec.h"
#include "models/ground/material.h"

namespace repose {

// Options of the ground model that are part of the scene (not fitted).
struct GroundModelSpec {
  bool sweep = true;             // sweep translating objects between frames
  int substeps = 1;              // substeps per frame when not sweeping, [1, 10000]
  double max_substep_angle_rad = 0.08726646259971647;  // rotation per substep for rotating objects (5 deg), [0.01, 180] deg
  int erosion_memory_steps = 30; // steps an eroded cell keeps eroding, [0, 65000]
  int coarse_factor = 2;         // coarsening of the grid for 'simple' or far objects, [1, 64]
  double far_distance_m = 0.0;   // objects farther than this from the camera use the coarse grid (0: never)
  enum class Collision { kOsmesa, kCpu };
  Collision collision = Collision::kCpu;
  // The bed inclined by this angle, falling along +x, as the dem section's
  // slope_deg: the grid is bed-aligned (x down the slope, heights normal to
  // the bed) and gravity is tilted. Erosion's repose rule then holds in the
  // world frame (erosion.h: inclined bed). [0, 80) deg; 0: a level ground.
  double bed_slope_rad = 0.0;
  // How displaced material is laid on open ground beside an object
  // (excess_routing.h): kPortions, in up to 16 portions each swept outwards
  // ring by ring (the default, which every committed calibration used);
  // kOnePass, the heap at the angle of repose laid at once
  // (heap_in_one_pass.h): faster, a different heap.
  enum class HeapLaying { kPortions, kOnePass };
  HeapLaying heap_laying = HeapLaying::kPortions;
};

// Throws FieldError naming the field and the rule. The loader and
// build_ground_model call this one rule.
void validate(const GroundModelSpec& spec);

template <class Visitor>
void ground_model_fields(Visitor& v, GroundModelSpec& g) {
  v.boolean("sweep", g.sweep);
  v.integer("substeps", g.substeps, IntRange{});
  v.angle_deg("max_substep_angle_deg", g.max_substep_angle_rad, Range::any());
  v.integer("erosion_memory_steps", g.erosion_memory_steps, IntRange{});
  v.integer("coarse_factor", g.coarse_factor, IntRange{});
  v.number("far_distance_m", g.far_distance_m, Range::any());
  using C = GroundModelSpec::Collision;
  v.choice("collision", g.collision, std::vector<std::pair<std::string, C>>{{"cpu", C::kCpu}, {"osmesa", C::kOsmesa}});
  v.angle_deg("bed_slope_deg", g.bed_slope_rad, Range::any());
  using H = GroundModelSpec::HeapLaying;
  v.choice("heap_laying", g.heap_laying,
           std::vector<std::pair<std::string, H>>{{"portions", H::kPortions}, {"one_pass", H::kOnePass}});
}

class GroundModelSection final : public SceneSection {
 public:
  static constexpr const char* kKey = "ground_model";

  GroundModelSpec options;
  std::map<std::string, Material> materials;  // defined in the section (presets need no entry)
  FreeBodySpec free_bodies;                   // free_bodies: and bearing: (only used with dynamic: objects)

  // The material of that name: defined here, else the preset. InputError
  // when it is neither.
  Material material(const std::string& name) const;
  void write_yaml(YAML::Emitter& out) const override;
  std::string summary() const override;
};

// The scene's ground-model section, or the defaults when it has none (a
// scene made in code).
const GroundModelSection& ground_model_section(const Scene& scene);

// A copy of the scene whose ground-model section has these options / this
// material defined (for scenes changed in code: the ladder, tests).
Scene with_ground_options(Scene scene, const GroundModelSpec& options);
Scene with_material(Scene scene, const Material& material);
// A copy of the scene with its ground-model options changed by change(GroundModelSpec&).
template <class Change>
Scene with_ground_options_changed(Scene scene, Change change) {
  GroundModelSpec options = ground_model_section(scene).options;
  change(options);
  return with_ground_options(std::move(scene), options);
}

// Reads `ground_model:` (yaml null: the defaults) and checks every material
// the common scene names.
std::shared_ptr<const SceneSection> read_ground_model_section(const YamlValue& value, const Scene& common);
SectionType ground_model_section_type();

}  // namespace repose
