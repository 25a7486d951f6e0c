#include "validation/observables/observable_spec.h"

namespace repose {

const char* observable_kind_name(ObservableSpec::Kind kind) {
  switch (kind) {
    case ObservableSpec::Kind::kHeightField: return "height_field";
    case ObservableSpec::Kind::kTransect: return "transect";
    case ObservableSpec::Kind::kCraterDepth: return "crater_depth";
    case ObservableSpec::Kind::kRimHeight: return "rim_height";
    case ObservableSpec::Kind::kPileAngle: return "pile_angle";
    case ObservableSpec::Kind::kFurrowArea: return "furrow_area";
    case ObservableSpec::Kind::kSeries: return "series";
    case ObservableSpec::Kind::kMeasure: return "measure";
    case ObservableSpec::Kind::kHeapFlank: return "heap_flank";
  }
  return "?";
}

}  // namespace repose
