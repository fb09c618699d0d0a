#include "sim/ray_map.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <mutex>
#include <sstream>
#include <utility>

#include <ceres/jet.h>
#include <opencv2/core/utility.hpp>

#include "models/distortion_function.h"

namespace ws {
namespace {

// The inverse of the radial map g(r) = r (1 + D(r)) on [0, rd_max]: exact at
// evenly spaced distorted radii (Newton), cubic Hermite in between (the
// derivative of the inverse is 1 / g'). Beyond the first radius where g stops
// increasing the inverse is undefined.
class RadialInverse {
 public:
  RadialInverse(const Distortion& distortion, double rd_max, int intervals) {
    const DistortionFunction function(distortion);
    using Jet = ceres::Jet<double, 1>;
    const int n = std::visit([](const auto& model) { return model.NumCoeffs(); }, function.model());
    const std::vector<Jet> jet_coeffs(function.coeffs(), function.coeffs() + n);
    auto g = [&](double r, double* slope) {
      return std::visit(
          [&](const auto& model) {
            using Jet = ceres::Jet<double, 1>;
            const Jet jr(r, 0);
            const Jet height = jr * (1.0 + model.RadialDistortion(jet_coeffs.data(), jr));
            *slope = height.v[0];
            return height.a;
          },
          function.model());
    };
    step_ = rd_max / intervals;
    double r = 0, slope = 0;
    g(0, &slope);
    if (!(slope > 0)) return;
    r_.push_back(0);
    slope_.push_back(1 / slope);
    for (int k = 1; k <= intervals; ++k) {
      const double target = k * step_;
      double x = r + step_ * slope_.back();  // one Newton step from the previous root
      bool converged = false;
      for (int iteration = 0; iteration < 50; ++iteration) {
        double d = 0;
        const double value = g(x, &d);
        if (!(d > 0) || !std::isfinite(value)) break;
        const double delta = (value - target) / d;
        x -= delta;
        if (std::abs(delta) <= 1e-14 * (1 + x)) {  // quadratic convergence: x is now exact to rounding
          converged = true;
          break;
        }
      }
      double d = 0;
      g(x, &d);
      if (!converged || !(d > 0) || !(x > r)) break;
      // g must increase all the way from the previous root (no fold in between).
      bool increasing = true;
      for (int s = 1; s < 4 && increasing; ++s) {
        double ds = 0;
        g(r + (x - r) * s / 4, &ds);
        increasing = ds > 0;
      }
      if (!increasing) break;
      r = x;
      r_.push_back(x);
      slope_.push_back(1 / d);
    }
  }

  // The ideal radius of distorted radius rd; false beyond the valid range.
  bool operator()(double rd, double* r) const {
    const double t = rd / step_;
    const size_t k = size_t(t);
    if (k + 1 >= r_.size()) {
      if (k + 1 == r_.size() && t == double(k)) {
        *r = r_[k];
        return true;
      }
      return false;
    }
    const double s = t - double(k), h = step_;
    const double s2 = s * s, s3 = s2 * s;
    *r = (2 * s3 - 3 * s2 + 1) * r_[k] + (s3 - 2 * s2 + s) * h * slope_[k] +
         (-2 * s3 + 3 * s2) * r_[k + 1] + (s3 - s2) * h * slope_[k + 1];
    return true;
  }

 private:
  double step_ = 1;
  std::vector<double> r_, slope_;
};

std::string Key(const CameraModel& m, double max_theta) {
  std::ostringstream out;
  out.precision(17);
  out << max_theta << ' ' << m.image_width << ' ' << m.image_height << ' ' << m.fx << ' ' << m.fy << ' ' << m.cx << ' '
      << m.cy << ' ' << m.p1 << ' ' << m.p2 << ' ' << m.distortion.kind << ' ' << m.distortion.degree;
  for (double k : m.distortion.knots) out << ' ' << k;
  out << " |";
  for (double c : m.distortion.coeffs) out << ' ' << c;
  out << " | " << m.nonradial.cols << ' ' << m.nonradial.rows;
  for (double d : m.nonradial.domain) out << ' ' << d;
  for (double c : m.nonradial.coeffs) out << ' ' << c;
  out << " | " << m.nonradial.tilt[0] << ' ' << m.nonradial.tilt[1];
  return out.str();
}

}  // namespace

RayMap::RayMap(const CameraModel& model, double max_theta)
    : cols_(model.image_width + 1), rows_(model.image_height + 1), rays_(size_t(cols_) * rows_) {
  const Camera camera(model);  // validates
  const double min_z = std::cos(max_theta);
  auto store = [&](int i, int j, const double* ray) {
    rays_[size_t(j) * cols_ + i] = ray && (max_theta >= M_PI || ray[2] >= min_z)
                                       ? cv::Vec3f(float(ray[0]), float(ray[1]), float(ray[2]))
                                       : cv::Vec3f(0, 0, 0);
  };
  auto vertex = [&](int i, int j) { return cv::Vec2d(i - 0.5, j - 0.5); };
  if (model.p1 == 0 && model.p2 == 0 && model.nonradial.empty()) {
    double rd_max = 0;
    for (int j : {0, rows_ - 1})
      for (int i : {0, cols_ - 1}) {
        const cv::Vec2d p = vertex(i, j);
        rd_max = std::max(rd_max, std::hypot((p[0] - model.cx) / model.fx, (p[1] - model.cy) / model.fy));
      }
    // The principal point may lie outside the image: then the farthest
    // vertex is still a corner, and the nearest does not matter.
    const RadialInverse inverse(model.distortion, rd_max * (1 + 1e-9), 16384);
    // The ray of ideal coordinates: (x, y, 1) normalized, or by the angle (radial_coordinate.h).
    const DistortionFunction function(model.distortion);
    auto ray_of = [&](const double ideal[2], double ray[3]) {
      return std::visit([&](const auto& m) { return std::decay_t<decltype(m)>::Coordinate::Ray(ideal, ray); },
                        function.model());
    };
    cv::parallel_for_(cv::Range(0, rows_), [&](const cv::Range& range) {
      for (int j = range.start; j < range.end; ++j)
        for (int i = 0; i < cols_; ++i) {
          const cv::Vec2d p = vertex(i, j);
          const double xd = (p[0] - model.cx) / model.fx, yd = (p[1] - model.cy) / model.fy;
          const double rd = std::hypot(xd, yd);
          double r = 0, ray[3] = {0, 0, 1};
          bool found = rd == 0;
          if (!found && inverse(rd, &r)) {
            const double ideal[2] = {xd * r / rd, yd * r / rd};
            found = ray_of(ideal, ray);
          }
          store(i, j, found ? ray : nullptr);
        }
    });
  } else {
    cv::parallel_for_(cv::Range(0, rows_), [&](const cv::Range& range) {
      for (int j = range.start; j < range.end; ++j)
        for (int i = 0; i < cols_; ++i) {
          const cv::Vec2d p = vertex(i, j);
          const auto ray = camera.Unproject(Eigen::Vector2d(p[0], p[1]));
          store(i, j, ray ? ray->data() : nullptr);
        }
    });
  }
  invalid_ = int(std::count_if(rays_.begin(), rays_.end(), [](const cv::Vec3f& r) { return !IsRay(r); }));
}

std::shared_ptr<const RayMap> RayMap::For(const CameraModel& model, double max_theta) {
  static std::mutex mutex;
  static std::deque<std::pair<std::string, std::shared_ptr<const RayMap>>> cache;
  const std::string key = Key(model, max_theta);
  {
    std::lock_guard<std::mutex> lock(mutex);
    for (const auto& [k, map] : cache)
      if (k == key) return map;
  }
  auto map = std::make_shared<const RayMap>(model, max_theta);
  std::lock_guard<std::mutex> lock(mutex);
  for (const auto& [k, existing] : cache)
    if (k == key) return existing;
  cache.emplace_back(key, map);
  if (cache.size() > 4) cache.pop_front();
  return map;
}

std::optional<cv::Vec3d> RayMap::Interpolate(double x, double y) const {
  const double u = x + 0.5, v = y + 0.5;
  const int i = std::clamp(int(std::floor(u)), 0, cols_ - 2);
  const int j = std::clamp(int(std::floor(v)), 0, rows_ - 2);
  const double a = u - i, b = v - j;
  if (!Valid(i, j) || !Valid(i + 1, j) || !Valid(i, j + 1) || !Valid(i + 1, j + 1)) return std::nullopt;
  const cv::Vec3d r00 = Ray(i, j), r10 = Ray(i + 1, j), r01 = Ray(i, j + 1), r11 = Ray(i + 1, j + 1);
  return (1 - a) * (1 - b) * r00 + a * (1 - b) * r10 + (1 - a) * b * r01 + a * b * r11;
}

double RayMap::MaxInterpolationErrorPx(const Camera& camera, int samples_per_side) const {
  const double w = cols_ - 1, h = rows_ - 1;
  std::vector<cv::Point2d> points = {{-0.5, -0.5}, {w - 0.5, -0.5}, {-0.5, h - 0.5}, {w - 0.5, h - 0.5}};
  for (int j = 0; j < samples_per_side; ++j)
    for (int i = 0; i < samples_per_side; ++i)
      // Irrational-ish offsets so that the samples fall at all sub-pixel positions.
      points.push_back({-0.5 + w * (i + 0.5 + 0.41 * std::sin(7.1 * j)) / samples_per_side,
                        -0.5 + h * (j + 0.5 + 0.41 * std::cos(5.3 * i)) / samples_per_side});
  double worst = 0;
  for (const auto& p : points) {
    const auto ray = Interpolate(p.x, p.y);
    if (!ray) continue;
    const auto pixel = camera.Project(Eigen::Vector3d((*ray)[0], (*ray)[1], (*ray)[2]));
    if (!pixel) return INFINITY;
    worst = std::max(worst, std::hypot((*pixel)[0] - p.x, (*pixel)[1] - p.y));
  }
  return worst;
}

std::vector<Eigen::Vector3d> RaysAround(double theta, int n) {
  std::vector<Eigen::Vector3d> rays;
  for (int i = 0; i < n; ++i) {
    const double azimuth = 2 * M_PI * i / n;
    rays.emplace_back(std::sin(theta) * std::cos(azimuth), std::sin(theta) * std::sin(azimuth), std::cos(theta));
  }
  return rays;
}

}  // namespace ws
