#include "calib/half_turn.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

#include "calib/solver/quality.h"

namespace ws::calib {
namespace {

const Eigen::Matrix3d kM = Eigen::Vector3d(-1, -1, 1).asDiagonal();  // H's rotation

double Angle(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  const double c = 0.5 * ((a.transpose() * b).trace() - 1);
  return std::acos(std::clamp(c, -1.0, 1.0));
}

Eigen::Vector3d HalfTurned(const BoardExtent& e, const Eigen::Vector3d& X) {
  return {e.x_min + e.x_max - X.x(), e.y_min + e.y_max - X.y(), X.z()};
}

// Board points to ids, over every view of both cameras (positions rounded
// to a micrometre).
using IdOf = std::map<std::pair<long, long>, int>;
std::pair<long, long> Key(const Eigen::Vector3d& X) {
  return {std::lround(X.x() * 1e6), std::lround(X.y() * 1e6)};
}
IdOf BoardIds(const MonoState& left, const MonoState& right) {
  IdOf ids;
  for (const MonoState* s : {&left, &right})
    for (const BoardView& view : s->prepared.views)
      for (int i = 0; i < view.size(); ++i) ids[Key(view.object[i])] = view.ids[i];
  return ids;
}

// The view with its order half-turned; false when a half-turned point is no
// corner of the board.
bool HalfTurnView(const BoardExtent& board, const IdOf& ids, BoardView* view) {
  BoardView turned = *view;
  for (int i = 0; i < view->size(); ++i) {
    turned.object[i] = HalfTurned(board, view->object[i]);
    const auto id = ids.find(Key(turned.object[i]));
    if (id == ids.end()) return false;
    turned.ids[i] = id->second;
  }
  *view = turned;
  return true;
}

}  // namespace

std::vector<int> MakeHalfTurnsConsistent(const BoardExtent& board,
                                         const std::vector<bool>& is_stereo,
                                         const MonoState& left, MonoState* right) {
  // Per stereo view, the relative rotation as detected [0] and half-turned [1].
  std::vector<int> views;
  std::vector<std::array<Eigen::Matrix3d, 2>> relative;
  for (size_t v = 0; v < is_stereo.size(); ++v) {
    if (!is_stereo[v]) continue;
    const Eigen::Matrix3d Rl = left.poses[v].R(), Rr = right->poses[v].R();
    views.push_back(int(v));
    relative.push_back({Rr * Rl.transpose(), Rr * kM * Rl.transpose()});
  }
  const size_t n = views.size();
  if (n < 2) return {};
  Eigen::Matrix3d rig;
  double best = std::numeric_limits<double>::infinity();
  for (size_t a = 0; a < n; ++a)
    for (int k = 0; k < 2; ++k) {
      std::vector<double> nearest;
      for (size_t b = 0; b < n; ++b)
        if (b != a)
          nearest.push_back(std::min(Angle(relative[a][k], relative[b][0]),
                                     Angle(relative[a][k], relative[b][1])));
      const double median = Median(nearest);
      if (median < best) {
        best = median;
        rig = relative[a][k];
      }
    }
  const IdOf ids = BoardIds(left, *right);
  std::vector<int> turned;
  for (size_t j = 0; j < n; ++j) {
    if (!(Angle(relative[j][1], rig) < Angle(relative[j][0], rig))) continue;
    const int v = views[j];
    if (!HalfTurnView(board, ids, &right->prepared.views[v])) continue;
    const Pose& pose = right->poses[v];  // pose * H: R M X + (R c + t), c = H(0)
    right->poses[v] = Pose::FromRt(pose.R() * kM, pose * HalfTurned(board, Eigen::Vector3d::Zero()));
    turned.push_back(v);
  }
  return turned;
}

}  // namespace ws::calib
