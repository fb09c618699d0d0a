#include "calib/solver/calib_data.h"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <set>

namespace ws::calib {

void StereoData::Add(const BoardView& left_view, const BoardView& right_view) {
  left.views.push_back(left_view);
  right.views.push_back(right_view);
}

std::string ViewProblem(const BoardView& view, int min_points) {
  if (view.size() < min_points)
    return std::to_string(view.size()) + " corners (at least " + std::to_string(min_points) +
           " needed)";
  if (view.ids.size() != view.image.size() || view.object.size() != view.image.size())
    return "ids, image and object points differ in number";
  std::set<int> ids(view.ids.begin(), view.ids.end());
  if (static_cast<int>(ids.size()) != view.size()) return "repeated corner ids";
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& p : view.object) mean += p;
  mean /= view.size();
  double extent = 0;
  for (const auto& p : view.object) {
    if (std::abs(p.z()) > 1e-9 * (1.0 + p.head<2>().norm()))
      return "object points are not on the board plane z = 0";
    extent = std::max(extent, (p - mean).norm());
  }
  if (!(extent > 0)) return "all object points coincide";
  // The spread of the corners across the board, perpendicular to their main
  // direction: collinear corners give no homography.
  Eigen::MatrixXd centred(view.size(), 2);
  for (int i = 0; i < view.size(); ++i) centred.row(i) = (view.object[i] - mean).head<2>() / extent;
  const Eigen::Vector2d sv = Eigen::JacobiSVD<Eigen::MatrixXd>(centred).singularValues();
  if (sv(1) < 0.05 * sv(0)) return "the corners are (nearly) collinear on the board";
  Eigen::Vector2d image_mean = Eigen::Vector2d::Zero();
  for (const auto& p : view.image) image_mean += p;
  image_mean /= view.size();
  Eigen::MatrixXd image_centred(view.size(), 2);
  double image_extent = 0;
  for (const auto& p : view.image) image_extent = std::max(image_extent, (p - image_mean).norm());
  if (!(image_extent > 0)) return "all image points coincide";
  for (int i = 0; i < view.size(); ++i)
    image_centred.row(i) = (view.image[i] - image_mean) / image_extent;
  const Eigen::Vector2d isv = Eigen::JacobiSVD<Eigen::MatrixXd>(image_centred).singularValues();
  if (isv(1) < 0.02 * isv(0)) return "the corners are (nearly) collinear in the image";
  return "";
}

BoardView CleanView(const BoardView& view, int* dropped) {
  BoardView clean;
  int bad = 0;
  const size_t n = std::min({view.ids.size(), view.image.size(), view.object.size()});
  bad += static_cast<int>(std::max({view.ids.size(), view.image.size(), view.object.size()}) - n);
  for (size_t i = 0; i < n; ++i) {
    if (!view.image[i].allFinite() || !view.object[i].allFinite()) {
      ++bad;
      continue;
    }
    clean.ids.push_back(view.ids[i]);
    clean.object.push_back(view.object[i]);
    clean.image.push_back(view.image[i]);
  }
  if (dropped) *dropped = bad;
  return clean;
}

std::vector<double> NeighbourSpacing(const BoardView& view) {
  double step = INFINITY;
  for (int i = 0; i < view.size(); ++i)
    for (int j = i + 1; j < view.size(); ++j) {
      const double d = (view.object[i] - view.object[j]).norm();
      if (d > 0) step = std::min(step, d);
    }
  std::vector<double> spacing(view.size(), INFINITY);
  for (int i = 0; i < view.size(); ++i)
    for (int j = 0; j < view.size(); ++j)
      if (i != j && (view.object[i] - view.object[j]).norm() < 1.01 * step)
        spacing[i] = std::min(spacing[i], (view.image[i] - view.image[j]).norm());
  for (double& s : spacing)
    if (!std::isfinite(s)) s = 0;
  return spacing;
}

}  // namespace ws::calib
