#pragma once
// The scene file's `terrain:` section, read into a TerrainScene. SI units;
// the slope in degrees at the file edge only.
//
//   terrain:
//     key_contours:                    # or key_contours_file: hills.geojson
//       - {name: foot, height_m: 0, points_m: [[0, 0], [100, 0], [100, 80], [0, 80]]}
//     contour_interval_m: 2            # defaults as in TerrainOptions
//     slope_deg: 30
//     smoothing_tolerance_m: 0.5
//     sample_spacing_m: 2
//     cell_size_m: 2
//     elements:                        # optional
//       region_m: [[10, 10], [30, 10], [30, 30], [10, 30]]
//       gap_fraction: 0.01
//       layers: [{name: bed, radius_m: 1, rows: 2, friction: 0.6, restitution: 0.1}]
//     buildings:                       # optional
//       - {name: house, footprint_m: [[...]], storeys: 2, storey_height_m: 3, gap_m: 0.02}
//
// A relative key_contours_file is taken from the scene file's folder.

#include "models/core/config/yaml_reader.h"
#include "models/terrain/terrain_scene.h"

namespace repose {

// Throws InputError (FILE:LINE:COL: KEY.PATH: ...) for a malformed section,
// and validates the result (TerrainScene::validate).
TerrainScene read_terrain_section(const YamlValue& section);

}  // namespace repose
