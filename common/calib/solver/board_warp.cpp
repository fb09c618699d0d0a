#include "calib/solver/board_warp.h"

#include <algorithm>
#include <limits>

namespace ws::calib {

BoardExtent ExtentOf(const std::vector<const CameraData*>& cameras) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  BoardExtent e{inf, -inf, inf, -inf};
  for (const CameraData* camera : cameras)
    for (const BoardView& view : camera->views)
      for (const Eigen::Vector3d& X : view.object) {
        e.x_min = std::min(e.x_min, X.x());
        e.x_max = std::max(e.x_max, X.x());
        e.y_min = std::min(e.y_min, X.y());
        e.y_max = std::max(e.y_max, X.y());
      }
  if (!(e.x_max > e.x_min)) e.x_min = 0, e.x_max = 1;
  if (!(e.y_max > e.y_min)) e.y_min = 0, e.y_max = 1;
  return e;
}

Eigen::Vector2d WarpBasis(const BoardExtent& e, const Eigen::Vector3d& X) {
  const double s = (X.x() - e.x_min) / (e.x_max - e.x_min);
  const double t = (X.y() - e.y_min) / (e.y_max - e.y_min);
  return {4 * s * (1 - s), 4 * t * (1 - t)};
}

}  // namespace ws::calib
