#pragma once
// The fixed options of the snow model (the scene's `snow:` section), in SI
// units and radians; degrees only in the scene file. What a fit changes (the
// snow angle of repose, the direction spread) is in SnowParams instead.

#include <string>
#include <vector>

#include "models/snow/snow_picture_options.h"
#include "models/snow/snowfall_directions.h"
#include "models/snow/snowfall_rate.h"
#include "models/snow/top_down_renderer.h"

namespace repose {

// Largest stable fraction of the excess moved per stabilisation pass; the
// analysis is in stabilisation.h (the same Jacobi bound as the ground's sigma).
inline constexpr double kSnowMovedFractionMax = 0.25;

// A group of objects with one snow map (the snow paper 2.1, Fig. 1): objects
// that do not overlap seen from above. The ground is a group of its own.
struct SnowGroupSpec {
  std::string name;
  bool ground = false;               // the ground height field (then no objects)
  std::vector<std::string> objects;  // names of scene objects (posed at t = 0)
};

struct SnowOptions {
  // One snow map each, in this order; at least one, names unique.
  std::vector<SnowGroupSpec> groups;
  // The main snowfall direction (tilt from straight down <= kMaxFallTiltRad).
  SnowfallDirection main_direction;
  // Shadow maps (snowfall directions) per probability estimate. [1, 65536]
  int direction_count = 64;
  // Side of a snow-map cell; 0 takes the ground's cell size. The maps share
  // one grid over the ground's extent. [0, inf)
  double cell_size_m = 0.0;
  // Shadow-map pixel = cell_size_m / shadow_oversampling. [1, 16]
  int shadow_oversampling = 1;
  // A point is lit when nothing lies more than this many shadow-map pixels
  // (times 1 + tan(tilt of the direction)) above it along the direction:
  // hides the sampling error of a surface against itself. [0, 16]
  double shadow_bias_cells = 1.0;
  // M(t), metres of snow per second on open level ground.
  SnowfallRate snowfall{1.0e-3};
  // Fraction of the excess over the angle of repose moved per pass, (0, 1/4].
  double moved_fraction = 0.2;
  // Stabilisation passes per time step at most; it stops earlier when settled. [1, 1e6]
  int max_stabilisation_passes = 50;
  // Excess height over the repose slope that is left alone (m). (0, inf)
  double settle_tolerance_m = 1.0e-6;
  SnowRenderer renderer = SnowRenderer::kCpu;
  // How P is computed: shadow maps (the paper's method) or the ray-cast
  // baseline of its Table 1 (ray_cast_probability.h), for comparisons.
  enum class Probability { kShadowMaps, kRayCast };
  Probability probability = Probability::kShadowMaps;
  // Pictures and animation frames of a run (figures only).
  SnowPictureOptions pictures;
};

// Throws FieldError (an InputError) naming the scene key (snow_section.h:
// direction_tilt_deg, moved_fraction, ...) and its rule; the section's
// reader and build_snow_model call this one rule.
void validate(const SnowOptions& options);

}  // namespace repose
