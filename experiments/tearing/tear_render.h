#pragma once
// A lit 3-D picture of the torn sheet (issue 15, item 4), rendered off-screen
// with OSMesa through the figures' renderer (experiments/figures/render_image.h,
// render_coloured_meshes): the deformed sheet as its intact cells, and in the
// torn cells the peeled, layered tear edge of tear_edge_layers.h composited in
// 3-D: per fibre layer and per fibre-image row, the torn cell's material left
// of that layer's cut goes with the left piece and the rest with the right
// piece, each layer's cut offset from the layer above along the tearing force
// (TearEdgeOptions::offset_direction), the lower layers drawn a little behind
// the top one (layer_spacing_m, exaggerated so that the peeled fringe shows).
// The top layer is green and the lower ones white, as in the seed's figure 1,
// each shaded by its fibre density; the viewer sits on the +z side, the side
// the right grip pulls towards.
//
// Departures: a torn cell's pieces are extended rigidly from the vertex column
// they hang on (the cell has no springs left, so its inside is not modelled);
// a layer's cut is kept inside the torn cell of its row nearest the top
// layer's cut, so a cut that the fibres push into an intact neighbour is drawn
// at that cell's edge; a piece's strip is left out where the vertex column it
// hangs on is itself torn apart (the tear turning sideways).

#include <string>

#include "experiments/figures/render_image.h"
#include "models/core/config/scene.h"
#include "models/core/io/png_io.h"
#include "models/tearing/fibre_image.h"
#include "models/tearing/sheet_model.h"
#include "models/tearing/sheet_state.h"
#include "models/tearing/tear_edge_layers.h"

namespace repose {

struct TearRenderOptions {
  int width_px = 800;
  int height_px = 600;
  // The camera looks at the middle of the sheet from the viewer's side (+z),
  // turned by azimuth about the vertical (+y) axis towards +x and raised by
  // elevation, each in (-90, 90) degrees; 0 and 0 is face on.
  double azimuth_deg = 35.0;
  double elevation_deg = 20.0;
  double fov_y_deg = 30.0;  // (0, 120)
  // How far behind the layer above each fibre layer is drawn (m), >= 0 and
  // below 1 mm.
  double layer_spacing_m = 0.2e-3;
  int supersample = 2;  // 1 to 4
  // 0: frame the whole sheet; > 0: a close-up framing a sphere of this
  // radius (m) around the tear's tip (the deepest point of its path), or the
  // whole sheet when nothing is torn.
  double close_up_m = 0.0;

  void validate() const;  // throws InputError naming the field
};

// The camera of TearRenderOptions, far enough that the whole deformed sheet
// (its bounding sphere) fits the view.
CameraSpec tear_camera(const SheetModel& model, const SheetState& state, const TearRenderOptions& options);

// The sheet's pieces as coloured meshes: the intact cells, then per layer the
// torn cells' strips (empty when nothing is torn).
std::vector<ColouredMesh> tear_meshes(const SheetModel& model, const SheetState& state, const FibreImages& images,
                                      const LayerCuts& cuts, const TearRenderOptions& options);

RgbImage render_tear(const SheetModel& model, const SheetState& state, const FibreImages& images,
                     const TearEdgeOptions& edge, const TearRenderOptions& options);

}  // namespace repose
