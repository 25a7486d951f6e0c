#pragma once
// A picture of the tear for looking at, not measuring: the composite fibre
// density in grey (dense = dark, like paper held against the light) with
// the torn cells in red and the notch in blue, seen from the viewer (+z),
// in the sheet's rest coordinates, `pixels_per_cell` pixels per cell.

#include "models/core/io/png_io.h"
#include "models/tearing/fibre_image.h"
#include "models/tearing/sheet_model.h"
#include "models/tearing/sheet_state.h"

namespace repose {

RgbImage draw_tear_image(const SheetModel& model, const SheetState& state, const FibreImages& images,
                         int pixels_per_cell);

}  // namespace repose
