#include "synthetic_rig.h"

#include <Eigen/Geometry>
#include <cmath>
#include <random>

#include "models/fisheye_lens.h"
#include "models/theia_lens.h"

namespace ws::calib {
namespace {

double Halton(int index, int base) {
  double f = 1, r = 0;
  for (int i = index; i > 0; i /= base) {
    f /= base;
    r += f * (i % base);
  }
  return r;
}

// Box-Muller on a fixed engine: the same numbers on every platform.
class Noise {
 public:
  explicit Noise(uint64_t seed) : engine_(seed) {}
  double Uniform() { return (engine_() >> 11) * (1.0 / 9007199254740992.0); }
  double Uniform(double a, double b) { return a + (b - a) * Uniform(); }
  double Gaussian() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    double u = 0;
    while (u <= 1e-300) u = Uniform();
    const double v = Uniform();
    const double m = std::sqrt(-2 * std::log(u));
    spare_ = m * std::sin(2 * M_PI * v);
    has_spare_ = true;
    return m * std::cos(2 * M_PI * v);
  }

 private:
  std::mt19937_64 engine_;
  bool has_spare_ = false;
  double spare_ = 0;
};

bool Inside(const Eigen::Vector2d& p, const CameraModel& c, double margin) {
  return p.x() >= margin - 0.5 && p.y() >= margin - 0.5 && p.x() <= c.image_width - 0.5 - margin &&
         p.y() <= c.image_height - 0.5 - margin;
}

// The corners of the board under `pose` that `camera` sees inside its image:
// their flat board coordinates `object`, imaged where the (bowed) board has
// them, `shape`.
BoardView See(const Camera& camera, const Pose& pose, const std::vector<Eigen::Vector3d>& object,
              const std::vector<Eigen::Vector3d>& shape, double margin, double max_theta) {
  BoardView view;
  for (int id = 0; id < static_cast<int>(object.size()); ++id) {
    const Eigen::Vector3d X = pose * shape[id];
    // Rays more than 85 degrees off axis are never imaged by a pinhole
    // model's lens; an angle model's reach as far as its image circle.
    if (!camera.IsAngleModel() && (X.z() <= 0.05 || X.head<2>().norm() > 11 * X.z())) continue;
    if (std::atan2(X.head<2>().norm(), X.z()) > max_theta) continue;
    const auto pixel = camera.Project(X);
    if (!pixel || !Inside(*pixel, camera.model(), margin)) continue;
    // Past the radius where a model's curve folds back (r (1 + D(r)) stops
    // increasing) a point lands in the image again, but no lens images it.
    const auto ray = camera.Unproject(*pixel);
    if (!ray || (*ray - X.normalized()).norm() > 1e-6) continue;
    view.ids.push_back(id);
    view.object.push_back(object[id]);
    view.image.push_back(*pixel);
  }
  return view;
}

}  // namespace

SyntheticRig MakeSyntheticRig(const SyntheticRigOptions& options) {
  const Camera left(options.left);
  const Camera right(options.stereo ? options.right : options.left);
  const Pose extrinsic = Pose::FromRt(options.R, options.T);
  std::vector<Eigen::Vector3d> object;
  for (int r = 0; r < options.board_rows; ++r)
    for (int c = 0; c < options.board_cols; ++c)
      object.emplace_back(c * options.square, r * options.square, 0);
  const Eigen::Vector3d centre((options.board_cols - 1) * options.square / 2,
                               (options.board_rows - 1) * options.square / 2, 0);
  const BoardWarp warp{options.board_warp, {0, 2 * centre.x(), 0, 2 * centre.y()}, false};
  std::vector<Eigen::Vector3d> shape;
  for (const Eigen::Vector3d& X : object) shape.push_back(Warped(warp, X));
  const int total = static_cast<int>(object.size());
  const double max_theta = options.max_theta_deg * M_PI / 180;

  SyntheticRig rig;
  rig.data.left.image_width = options.left.image_width;
  rig.data.left.image_height = options.left.image_height;
  rig.data.right.image_width = right.model().image_width;
  rig.data.right.image_height = right.model().image_height;
  Noise noise(options.seed);
  int halton = 1;
  for (int v = 0; v < options.views; ++v) {
    for (int attempt = 0;; ++attempt, ++halton) {
      if (attempt > 1000) throw std::runtime_error("synthetic rig: no visible board pose found");
      const double e = options.target_extent;
      const Eigen::Vector2d unit(Halton(halton, 2) - 0.5, Halton(halton, 3) - 0.5);
      const Eigen::Vector2d target((0.5 + e * unit.x()) * options.left.image_width - 0.5,
                                   (0.5 + e * unit.y()) * options.left.image_height - 0.5);
      const auto ray = left.Unproject(target);
      const double distance = noise.Uniform(options.min_distance, options.max_distance);
      const double tilt = noise.Uniform(options.min_tilt_deg, options.max_tilt_deg) * M_PI / 180;
      const double tilt_axis_angle = noise.Uniform(0, 2 * M_PI);
      const double roll = noise.Uniform(-M_PI, M_PI);
      if (!ray) continue;
      // Board z axis along the ray (away from the camera), then tilted and rolled.
      const Eigen::Vector3d z = ray->normalized();
      const Eigen::Vector3d a =
          std::abs(z.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
      const Eigen::Vector3d x = (a - a.dot(z) * z).normalized();
      const Eigen::Vector3d y = z.cross(x);
      Eigen::Matrix3d facing;
      facing << x, y, z;
      const Eigen::Vector3d tilt_axis =
          std::cos(tilt_axis_angle) * x + std::sin(tilt_axis_angle) * y;
      const Eigen::Matrix3d R =
          Eigen::AngleAxisd(tilt, tilt_axis).toRotationMatrix() * facing *
          Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitZ()).toRotationMatrix();
      const Pose pose = Pose::FromRt(R, distance * z - R * centre);
      BoardView lv = See(left, pose, object, shape, options.edge_margin_px, max_theta);
      if (lv.size() < options.min_visible * total) continue;
      const Pose right_pose =
          Pose::FromRt(extrinsic.R() * pose.R(), extrinsic.R() * pose.t() + extrinsic.t());
      BoardView rv;
      if (options.stereo) {
        rv = See(right, right_pose, object, shape, options.edge_margin_px, max_theta);
        if (rv.size() < options.min_visible * total) rv = BoardView();
      }
      for (auto* view : {&lv, &rv})
        for (auto& p : view->image)
          p += options.noise_px * Eigen::Vector2d(noise.Gaussian(), noise.Gaussian());
      rig.data.Add(lv, rv);
      rig.left_poses.push_back(pose);
      rig.right_poses.push_back(right_pose);
      ++halton;
      break;
    }
  }
  return rig;
}

CameraModel GaugeNormalized(const CameraModel& camera) {
  if (camera.distortion.kind != ModelKind::kBspline) return camera;
  const Camera c(camera);
  const double d0 = c.DistortionCurve(0.0);
  CameraModel out = camera;
  for (double& a : out.distortion.coeffs) a = (1 + a) / (1 + d0) - 1;
  out.fx *= 1 + d0;
  out.fy *= 1 + d0;
  out.p1 /= 1 + d0;
  out.p2 /= 1 + d0;
  return out;
}

CameraModel MustacheTestCamera(int variant) {
  CameraModel camera = TheiaLikeCamera();
  if (variant == 0) {
    camera.fy = camera.fx * 1.0015;
    camera.cx += 3.7;
    camera.cy -= 2.4;
    camera.p1 = 2e-4;
    camera.p2 = -1.5e-4;
  } else {
    camera.fx *= 0.996;
    camera.fy = camera.fx * 0.999;
    camera.cx -= 5.1;
    camera.cy += 4.2;
    camera.p1 = -1e-4;
    camera.p2 = 2.5e-4;
  }
  return GaugeNormalized(camera);
}

CameraModel FisheyeTestCamera(int variant) {
  CameraModel camera = FisheyeKneeCamera();
  if (variant != 0) camera.fx = 297.5;
  camera.fy = camera.fx * (variant == 0 ? 1.0012 : 0.9991);
  camera.cx += variant == 0 ? 4.1 : -3.3;
  camera.cy += variant == 0 ? -2.7 : 3.8;
  return camera;
}

CameraModel BarrelTestCamera(int variant) {
  CameraModel camera;
  camera.image_width = 1280;
  camera.image_height = 960;
  camera.fx = variant == 0 ? 700.0 : 694.0;
  camera.fy = camera.fx * (variant == 0 ? 1.001 : 0.9995);
  camera.cx = variant == 0 ? 642.5 : 636.1;
  camera.cy = variant == 0 ? 478.3 : 483.6;
  camera.p1 = variant == 0 ? 3e-4 : -2e-4;
  camera.p2 = variant == 0 ? -2e-4 : 1e-4;
  camera.distortion = Distortion{ModelKind::kPoly6, 0, {}, {-0.2, 0.05, -0.005}};
  if (variant != 0) camera.distortion.coeffs = {-0.19, 0.046, -0.0045};
  return camera;
}

}  // namespace ws::calib
