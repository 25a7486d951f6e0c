#pragma once
// A picture of a snow scene (figures only, no physics), drawn with OpenGL
// through OSMesa (models/core/gl/osmesa_context.h): the objects in grey, the
// ground in soil brown turning to snow white as its snow deepens, the snow
// on every object map in white (snow_surface_mesh.h), seen through an
// orthographic camera (SnowPictureOptions) and lit by one fixed sun plus
// ambient light, flat-shaded per triangle. The framing depends only on the
// model and the options (not on the snow), so the frames of a run line up.
// Deterministic: the same state gives the same bytes.

#include <memory>

#include "models/core/io/png_io.h"
#include "models/snow/snow_model.h"
#include "models/snow/snow_picture_options.h"
#include "models/snow/snow_state.h"

namespace repose {

class OsmesaContext;

// The background colour of a picture (sky grey-blue), RGB 0..255.
inline constexpr std::uint8_t kSnowPictureBackground[3] = {200, 214, 230};

class SnowPictureRenderer {
 public:
  // Validates the options; creates an OSMesa context (one per renderer,
  // used only on the creating thread). z_top_m: the highest the snow surface
  // is framed for (snow_picture_top_m).
  SnowPictureRenderer(const SnowModel& model, const SnowPictureOptions& options, double z_top_m);
  ~SnowPictureRenderer();
  SnowPictureRenderer(const SnowPictureRenderer&) = delete;
  SnowPictureRenderer& operator=(const SnowPictureRenderer&) = delete;

  RgbImage render(const SnowState& state);

 private:
  const SnowModel& model_;
  SnowPictureOptions options_;
  double z_top_m_;
  std::unique_ptr<OsmesaContext> context_;
};

// The framing's top: the highest object or ground plus twice the snow the
// run lets fall on open ground (snowfall over the duration, times the scale).
double snow_picture_top_m(const SnowModel& model, double snowfall_scale);

}  // namespace repose
