#include "models/terrain/edge_event.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "models/core/base/error.h"

namespace repose {

double interior_angle_rad(const Polygon2& polygon, std::size_t i) {
  const std::size_t n = polygon.size();
  REPOSE_DEMAND(n >= 3 && i < n);
  const Point2 to_prev = polygon[(i + n - 1) % n] - polygon[i];
  const Point2 to_next = polygon[(i + 1) % n] - polygon[i];
  // counter-clockwise: the interior lies to the left of the edges, i.e. the
  // angle measured counter-clockwise from to_next to to_prev
  double angle = std::atan2(to_next.x() * to_prev.y() - to_next.y() * to_prev.x(), to_next.dot(to_prev));
  if (angle < 0.0) angle += 2.0 * std::numbers::pi;
  return angle;
}

double edge_vanish_distance_m(const Polygon2& polygon, std::size_t i) {
  const std::size_t n = polygon.size();
  const double theta_i = interior_angle_rad(polygon, i);
  const double theta_next = interior_angle_rad(polygon, (i + 1) % n);
  if (!(0.5 * theta_i + 0.5 * theta_next < std::numbers::pi)) return std::numeric_limits<double>::infinity();
  const double length = (polygon[(i + 1) % n] - polygon[i]).norm();
  return length / (1.0 / std::tan(0.5 * theta_i) + 1.0 / std::tan(0.5 * theta_next));
}

double first_edge_event_distance_m(const Polygon2& polygon) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < polygon.size(); ++i) best = std::min(best, edge_vanish_distance_m(polygon, i));
  return best;
}

}  // namespace repose
