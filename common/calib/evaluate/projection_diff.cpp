#include "calib/evaluate/projection_diff.h"

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "calib/solver/quality.h"

namespace ws::calib {
namespace {

struct GridRay {
  int index = 0;
  Eigen::Vector2d pixel;
  Eigen::Vector3d ray;
};

Eigen::Matrix3d Rotation(const Eigen::Vector3d& angle_axis) {
  const double angle = angle_axis.norm();
  if (angle == 0) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(angle, angle_axis / angle).toRotationMatrix();
}

// project_B(R v) - q, or nullopt where B has no pixel inside its image.
std::optional<Eigen::Vector2d> Difference(const CameraProjection& b, const Eigen::Matrix3d& R,
                                          const GridRay& g) {
  const Eigen::Vector3d ray = R * g.ray;
  if (!b.InField(ray)) return std::nullopt;
  const auto pixel = b.Project(ray);
  if (!pixel || !pixel->allFinite()) return std::nullopt;
  if (pixel->x() < -0.5 || pixel->y() < -0.5 || pixel->x() > b.image_width() - 0.5 ||
      pixel->y() > b.image_height() - 0.5)
    return std::nullopt;
  return *pixel - g.pixel;
}

// Gauss-Newton on the angle-axis w of R over the rays (numerical Jacobian:
// three parameters, a small rotation), from w = 0.
Eigen::Matrix3d FitRotation(const CameraProjection& b, const std::vector<GridRay>& rays) {
  Eigen::Vector3d w = Eigen::Vector3d::Zero();
  const double h = 1e-7;
  for (int iteration = 0; iteration < 20; ++iteration) {
    Eigen::Matrix3d JtJ = Eigen::Matrix3d::Zero();
    Eigen::Vector3d Jtr = Eigen::Vector3d::Zero();
    const Eigen::Matrix3d R = Rotation(w);
    for (const GridRay& g : rays) {
      const auto r = Difference(b, R, g);
      if (!r) continue;
      Eigen::Matrix<double, 2, 3> J;
      bool ok = true;
      for (int k = 0; k < 3 && ok; ++k) {
        Eigen::Vector3d step = w;
        step[k] += h;
        const auto moved = Difference(b, Rotation(step), g);
        ok = moved.has_value();
        if (ok) J.col(k) = (*moved - *r) / h;
      }
      if (!ok) continue;
      JtJ += J.transpose() * J;
      Jtr += J.transpose() * *r;
    }
    const Eigen::Vector3d delta = JtJ.ldlt().solve(-Jtr);
    if (!delta.allFinite()) break;
    w += delta;
    if (delta.norm() < 1e-12) break;
  }
  return Rotation(w);
}

}  // namespace

double DefaultFitRadius(const CameraProjection& camera) {
  return std::min(camera.image_width(), camera.image_height()) / 6.0;
}

ProjectionDiff CompareProjection(const CameraProjection& a, const CameraProjection& b,
                                 double fit_radius, int cols, int rows) {
  const int width = a.image_width(), height = a.image_height();
  if (width != b.image_width() || height != b.image_height())
    throw std::invalid_argument(
        "the two cameras' images differ in size (" + std::to_string(width) + "x" +
        std::to_string(height) + " and " + std::to_string(b.image_width()) + "x" +
        std::to_string(b.image_height()) + "): not calibrations of one camera");
  ProjectionDiff out;
  out.grid = ImageGrid::Over(width, height, cols, rows);
  out.diff_px.assign(out.grid.size(), NAN);
  const Eigen::Vector2d centre((width - 1) / 2.0, (height - 1) / 2.0);
  std::vector<GridRay> all, central;
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < cols; ++i) {
      const Eigen::Vector2d q = out.grid.Pixel(i, j);
      const auto ray = a.Unproject(q);
      if (!ray || !a.InField(*ray)) continue;
      all.push_back({j * cols + i, q, *ray});
      if ((q - centre).norm() <= fit_radius) central.push_back(all.back());
    }
  if (fit_radius > 0 && !central.empty()) {
    out.rotation = FitRotation(b, central);
    out.rotation_deg = Eigen::AngleAxisd(out.rotation).angle() * 180 / M_PI;
    out.fit_points = int(central.size());
  }
  std::vector<double> compared;
  double sum = 0;
  for (const GridRay& g : all) {
    const auto r = Difference(b, out.rotation, g);
    if (!r) continue;
    out.diff_px[g.index] = r->norm();
    compared.push_back(r->norm());
    sum += r->squaredNorm();
  }
  out.points = int(compared.size());
  if (compared.empty())  // a difference over nothing is no difference
    throw std::runtime_error("no point of the " + std::to_string(cols) + " x " + std::to_string(rows) +
                             " grid projects through both cameras: nothing to compare (do they describe one "
                             "camera, of one image size?)");
  out.rms_px = std::sqrt(sum / compared.size());
  out.max_px = *std::max_element(compared.begin(), compared.end());
  out.median_px = Median(compared);
  return out;
}

}  // namespace ws::calib
