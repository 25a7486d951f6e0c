#pragma once
// The peeled, layered tear edge (the seed paper's section 3.3), drawn on
// the fibre images rather than modelled in the mesh: per fibre layer a cut
// line runs down the tear, each row's cut where that layer is thinnest, so
// the cut is jagged by the fibres; layer 1 (the top) walks from row to row
// within a few pixels of its last cut, and every lower layer starts from the
// cut of the layer above shifted along offset_direction (the side the
// tearing force pulls towards) and looks for its thinnest point around
// there. Drawn with the two pieces pulled apart by opening_m, each layer
// semi-transparent, the top layer green and the others white as in the
// seed's figure 1, the lower layers showing as a white fringe where the top
// layer has peeled back.
//
// Departures from the seed: its cut starts at the thinnest point of each
// cut spring and joins the two cut edges of a cell; here the cut is traced
// per image row within 1.5 cells of the tear path (tear_path.h), which
// gives one cut per layer for a tear running down the sheet. The picture is
// in rest coordinates (the mesh's deformation is not drawn).

#include <vector>

#include <Eigen/Core>

#include "models/core/io/png_io.h"
#include "models/tearing/fibre_image.h"
#include "models/tearing/sheet_model.h"
#include "models/tearing/sheet_state.h"

namespace repose {

struct TearEdgeOptions {
  // How far each layer's search starts from the layer above's cut (m).
  double layer_offset_m = 0.4e-3;
  // Unit in-plane direction of that shift (the side the force pulls to).
  Eigen::Vector2d offset_direction{1.0, 0.0};
  // How far from its start a cut may look for the thinnest point (m).
  double search_half_width_m = 0.75e-3;
  // Gap drawn between the two pieces (m).
  double opening_m = 1.0e-3;

  void validate() const;  // throws InputError naming the field
};

// Per layer, per image row (row 0 at the smallest y): the cut's x (m), or
// NaN in rows the tear does not reach.
struct LayerCuts {
  std::vector<std::vector<double>> cut_x_m;
};

LayerCuts trace_layer_cuts(const SheetModel& model, const SheetState& state, const FibreImages& images,
                           const TearEdgeOptions& options);

// The layers composited over a dark background at the images' resolution.
RgbImage draw_layered_tear_edge(const FibreImages& images, const LayerCuts& cuts, const TearEdgeOptions& options);

}  // namespace repose
