#pragma once
// The `dem_snowfall:` section of a scene: how the cohesive DEM snowfall
// reference (dem.initial: snowfall, snowfall_script.h) rains its grains.
// Optional; a scene without it runs with these defaults. What falls (the
// directions' distribution, the snow depth on open ground) is the scene's
// snow: section, so the heuristic and the reference see the same snowfall.
//
//   dem_snowfall: {stream_count: 16, fall_speed_m_s: 0.5, insert_time_s: 0.5,
//                  packing_fraction: 0.58, max_settle_time_s: 1.0}

#include <string>

#include "models/core/config/fields.h"
#include "models/core/config/scene.h"
#include "models/core/config/scene_section.h"
#include "models/core/config/yaml_reader.h"

namespace repose {

struct SnowfallOptions {
  // Insertion streams: each one rains grains along one direction drawn
  // (seeded) from the snow section's distribution. [1, 256]
  int stream_count = 16;
  // Terminal speed (m/s): grains enter at this speed along their direction,
  // and gravity acts only on grains slower than it, so snow falls in
  // straight lines (as the shadow maps assume) and a grain dropping off an
  // edge is capped at it, as air drag caps snow. [0.05, 10]
  double fall_speed_m_s = 0.5;
  // Grains enter at a constant rate over this time (s). [0.01, 100]
  double insert_time_s = 0.5;
  // Packing of the deposit assumed to size the grain count from the snow
  // section's depth on open ground. [0.1, 0.74]
  double packing_fraction = 0.58;
  // After the last grain has landed, settling runs until the kinetic energy
  // falls below dem.settle_kinetic_energy_j, at most this long (s); a run
  // that has not settled by then fails. [0.01, 100]
  double max_settle_time_s = 1.0;
};

template <class V, class O>
void snowfall_option_fields(V& v, O& o) {
  v.integer("stream_count", o.stream_count, IntRange{1, 256});
  v.number("fall_speed_m_s", o.fall_speed_m_s, Range::closed(0.05, 10.0));
  v.number("insert_time_s", o.insert_time_s, Range::closed(0.01, 100.0));
  v.number("packing_fraction", o.packing_fraction, Range::closed(0.1, 0.74));
  v.number("max_settle_time_s", o.max_settle_time_s, Range::closed(0.01, 100.0));
}

// Throws FieldError (an InputError) "KEY: expected RULE, got VALUE".
void validate(const SnowfallOptions& options);

class SnowfallSection final : public SceneSection {
 public:
  static constexpr const char* kKey = "dem_snowfall";
  SnowfallOptions options;
  void write_yaml(YAML::Emitter& out) const override;
  std::string summary() const override;
};

SectionType snowfall_section_type();

// The scene's snowfall options: its section's, or the defaults.
SnowfallOptions snowfall_options_of(const Scene& scene);

}  // namespace repose
