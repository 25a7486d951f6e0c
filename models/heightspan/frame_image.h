#pragma once
// A frame of a height-span run as a picture (figures only, no physics): on
// top, a vertical section through the scene along x at y = section_y_m
// (ground, the objects' solid spans, the material on them, particles
// within two cells of the section); below it, the scene seen from above,
// shaded by the top surface (ground, object, or material on the object).
// Colours: ground sand brown, objects grey, material carried light sand,
// particles dark. Deterministic: the same state gives the same bytes.

#include "models/core/io/png_io.h"

namespace repose {

struct HeightSpanModel;
struct HeightSpanState;

struct FrameView {
  double section_y_m = 0.0;
  double z_min_m = 0.0;  // the section's vertical extent
  double z_max_m = 0.1;
  int px_per_cell = 3;   // [1, 16]
};

RgbImage render_frame(const HeightSpanModel& model, const HeightSpanState& state, const FrameView& view);

}  // namespace repose
