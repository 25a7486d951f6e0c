#pragma once
// Key contours from a GeoJSON-like file (the GIS side of seed paper 003,
// sec. 4: key contours drawn on a map with their attributes):
//   {"type": "FeatureCollection", "features": [
//     {"type": "Feature", "properties": {"name": "foot", "height_m": 0.0},
//      "geometry": {"type": "Polygon", "coordinates": [[[x, y], ...]]}}]}
// Coordinates in metres in a local frame (no map projection). A ring closed
// GeoJSON-style (last point = first) is accepted; holes are refused (give an
// inner ring as its own key contour, with its own height).

#include <string>
#include <vector>

#include "models/terrain/key_contour.h"

namespace repose {

// Largest file read (bytes): a contour file is small; a bigger one is a mistake.
inline constexpr std::uintmax_t kMaxKeyContourFileBytes = 64u << 20;

// Throws InputError naming the file, the feature and what is wrong.
std::vector<KeyContour> read_key_contours(const std::string& path);
// Parses the text itself (source names it in errors).
std::vector<KeyContour> parse_key_contours(const std::string& text, const std::string& source);

}  // namespace repose
