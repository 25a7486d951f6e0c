#pragma once
// The order in which a drag's contact cells pass their material on
// (displacement.cpp, spread_rear_to_front): by position along the drag
// (i dx + j dy), then distance to the border (farthest first), then local
// index. Ties exchange nothing, so any fixed order would do; this one is
// the one the committed results were made with.

#include <vector>

#include "models/ground/contact_region.h"

namespace repose {

// The local indices of r.cells (ascending, as displacement lists them) in
// that order. A drag along a grid axis (most are) by two stable counting
// sorts; any other by a comparison sort.
std::vector<int> rear_to_front_order(const DragDirection& dir, const ContactRegion& r);

// The same order by the comparison sort, whatever the direction: the
// reference the counting sorts are tested against.
std::vector<int> rear_to_front_order_by_sort(const DragDirection& dir, const ContactRegion& r);

}  // namespace repose
