#include "rectify/rectification.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <opencv2/calib3d.hpp>
#include <opencv2/core/eigen.hpp>
#include <opencv2/imgproc.hpp>

#include "models/image_size.h"

namespace ws {
namespace {

// Bouguet's rectifying rotations for X_right = R X_left + T.
void BouguetRotations(const Rig& rig, cv::Matx33d* R_left, cv::Matx33d* R_right) {
  cv::Mat R, T;
  cv::eigen2cv(rig.R, R);
  cv::eigen2cv(rig.T, T);
  const cv::Mat K = cv::Mat::eye(3, 3, CV_64F);
  cv::Mat R1, R2, P1, P2, Q;
  cv::stereoRectify(K, cv::noArray(), K, cv::noArray(), cv::Size(2, 2), R, T, R1, R2, P1, P2, Q,
                    0);
  *R_left = cv::Matx33d(R1);
  *R_right = cv::Matx33d(R2);
}

// The lat-lon angles (psi, phi) of a ray in the rectified frame.
cv::Vec2d LatLon(const cv::Vec3d& p) {
  return {std::asin(std::clamp(p[0] / cv::norm(p), -1.0, 1.0)), std::atan2(p[1], p[2])};
}

// The tables of one camera: one pair per sample (rectification.h), and the
// pixels all of whose samples fall in the input image.
void BuildMaps(const Camera& camera, const cv::Matx33d& R_rect, const Rectification& rect,
               std::vector<std::array<cv::Mat, 2>>* maps, cv::Mat* valid) {
  const int n = rect.downscale;
  *valid = cv::Mat(rect.size, CV_8UC1, cv::Scalar(255));
  const cv::Matx33d to_camera = R_rect.t();
  const cv::Size input(camera.model().image_width, camera.model().image_height);
  maps->clear();
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      // Sample (i, j) of grid pixel (u, v): full-resolution pixel (n u + i, n v + j).
      const double du = (i + 0.5) / n - 0.5, dv = (j + 0.5) / n - 0.5;
      cv::Mat map_x(rect.size, CV_32FC1), map_y(rect.size, CV_32FC1);
      cv::parallel_for_(cv::Range(0, rect.size.height), [&](const cv::Range& rows) {
        for (int v = rows.start; v < rows.end; ++v) {
          float* mx = map_x.ptr<float>(v);
          float* my = map_y.ptr<float>(v);
          uint8_t* ok = valid->ptr<uint8_t>(v);
          for (int u = 0; u < rect.size.width; ++u) {
            const cv::Vec3d r = to_camera * RectifiedRay(rect, u + du, v + dv);
            const Eigen::Vector3d ray(r[0], r[1], r[2]);
            const auto pixel = camera.Project(ray);
            const bool inside = pixel && camera.InField(ray) && (*pixel)[0] >= -0.5 && (*pixel)[1] >= -0.5 &&
                                (*pixel)[0] <= input.width - 0.5 && (*pixel)[1] <= input.height - 0.5;
            mx[u] = inside ? float((*pixel)[0]) : -1.f;
            my[u] = inside ? float((*pixel)[1]) : -1.f;
            if (!inside) ok[u] = 0;
          }
        }
      });
      std::array<cv::Mat, 2> fixed;
      cv::convertMaps(map_x, map_y, fixed[0], fixed[1], CV_16SC2);
      maps->push_back(std::move(fixed));
    }
}

// The (psi, phi) box of the rays of a camera's pixels (sampled about 200
// times across the image) in its model's field turned by R_rect: psi over the rays of the
// central row (phi within `band` of 0), phi over those of the central
// column (psi within `band`), band the angle of 3 samples at the centre.
// Elsewhere a lens past 180 degrees wraps: its rays behind the cameras near
// the baseline have phi near 180 degrees (and near the epipoles, where |psi|
// nears 90 degrees, phi is not defined).
cv::Vec4d FieldBox(const Camera& camera, const cv::Matx33d& R_rect) {
  const CameraModel& m = camera.model();
  const double step = std::max(m.image_width, m.image_height) / 200.0;
  const double band = 3 * step / std::min(m.fx, m.fy);
  cv::Vec4d box(INFINITY, -INFINITY, INFINITY, -INFINITY);  // psi min, max, phi min, max
  for (double v = 0; v < m.image_height; v += step)
    for (double u = 0; u < m.image_width; u += step) {
      const auto ray = camera.Unproject(Eigen::Vector2d(u, v));
      if (!ray || !camera.InField(*ray)) continue;
      const cv::Vec2d a = LatLon(R_rect * cv::Vec3d((*ray)[0], (*ray)[1], (*ray)[2]));
      if (std::abs(a[1]) <= band) box[0] = std::min(box[0], a[0]), box[1] = std::max(box[1], a[0]);
      if (std::abs(a[0]) <= band) box[2] = std::min(box[2], a[1]), box[3] = std::max(box[3], a[1]);
    }
  return box;
}

// The two cameras' boxes intersected.
cv::Vec4d CommonBox(const Rig& rig, const cv::Matx33d& R_left, const cv::Matx33d& R_right) {
  const cv::Vec4d l = FieldBox(Camera(rig.left), R_left), r = FieldBox(Camera(rig.right), R_right);
  return {std::max(l[0], r[0]), std::min(l[1], r[1]), std::max(l[2], r[2]), std::min(l[3], r[3])};
}

// cv::remap of `region` (all of the maps when empty) into that part of *out;
// with several samples, their mean, rounded as cv::INTER_AREA rounds.
void Remap(const cv::Mat& in, const std::vector<std::array<cv::Mat, 2>>& maps, const cv::Rect& region,
           cv::Mat* out) {
  const cv::Size size = maps.front()[0].size();
  const cv::Rect r = region.empty() ? cv::Rect(cv::Point(), size) : region;
  if (r.size() == size)
    out->create(size, in.type());
  else
    *out = cv::Mat::zeros(size, in.type());
  cv::Mat part = (*out)(r);  // remap writes into it: same size and type
  if (maps.size() == 1) {
    cv::remap(in, part, maps[0][0](r), maps[0][1](r), cv::INTER_LINEAR, cv::BORDER_CONSTANT);
    return;
  }
  const bool integer = in.depth() <= CV_16S;
  const int sum_depth = in.depth() == CV_8U && maps.size() <= 256 ? CV_16U : integer ? CV_32S : CV_64F;
  cv::Mat sample, sum(r.size(), CV_MAKETYPE(sum_depth, in.channels()), cv::Scalar::all(0));
  for (const auto& m : maps) {
    cv::remap(in, sample, m[0](r), m[1](r), cv::INTER_LINEAR, cv::BORDER_CONSTANT);
    cv::add(sum, sample, sum, cv::noArray(), sum.type());
  }
  // The mean; an integer one with its halves rounded up, as the area downscale rounds.
  sum.convertTo(part, in.depth(), 1.0 / double(maps.size()), integer ? 1e-3 : 0.0);
}

}  // namespace

RectificationMode ParseRectificationMode(const std::string& name) {
  if (name == "pinhole") return RectificationMode::kPinhole;
  if (name == "latlon") return RectificationMode::kLatLon;
  if (name == "auto") return RectificationMode::kAuto;
  throw std::invalid_argument("rectification must be pinhole, latlon or auto, not '" + name + "'");
}

const char* RectificationModeName(RectificationMode mode) {
  switch (mode) {
    case RectificationMode::kPinhole: return "pinhole";
    case RectificationMode::kLatLon: return "latlon";
    case RectificationMode::kAuto: break;
  }
  return "auto";
}

Rectification BuildRectification(const Rig& rig, const RectifyOptions& options) {
  Rectification rect = RectificationGeometry(rig, options);
  BuildRectificationMaps(rig, &rect);
  return rect;
}

Rectification RectificationGeometry(const Rig& rig, const RectifyOptions& options) {
  const Camera left(rig.left), right(rig.right);  // throw for an inconsistent camera
  Rectification rect;
  rect.input_size = cv::Size(rig.left.image_width, rig.left.image_height);
  if (rect.input_size != cv::Size(rig.right.image_width, rig.right.image_height))
    throw std::invalid_argument("the two cameras of the rig have different image sizes");
  if (!(options.focal_scale > 0)) throw std::invalid_argument("focal_scale must be positive");
  if (options.downscale < 1 || options.downscale > 8) throw std::invalid_argument("downscale must be 1..8");
  BouguetRotations(rig, &rect.R_left, &rect.R_right);
  // The common field: auto's choice and lat-lon's image (a pinhole needs none).
  const cv::Vec4d box = options.mode == RectificationMode::kPinhole
                            ? cv::Vec4d()
                            : CommonBox(rig, rect.R_left, rect.R_right);
  rect.mode = options.mode;
  if (rect.mode == RectificationMode::kAuto) {
    const double widest = M_PI * 130 / 180;
    rect.mode = box[1] - box[0] <= widest && box[3] - box[2] <= widest ? RectificationMode::kPinhole
                                                                       : RectificationMode::kLatLon;
  }
  rect.f = options.focal_scale * std::min({rig.left.fx, rig.left.fy, rig.right.fx, rig.right.fy});
  if (rect.mode == RectificationMode::kPinhole) {
    rect.size = options.size.empty() ? rect.input_size : options.size;
    rect.cx = (rect.size.width - 1) / 2.0;
    rect.cy = (rect.size.height - 1) / 2.0;
  } else {
    if (!(box[1] > box[0] && box[3] > box[2]))
      throw std::invalid_argument("the two cameras of the rig see no common field");
    const double width = std::ceil((box[1] - box[0]) * rect.f) + 1, height = std::ceil((box[3] - box[2]) * rect.f) + 1;
    const bool acceptable = width <= 1e9 && height <= 1e9 && ImageSizeAcceptable(int64_t(width), int64_t(height));
    if (options.size.empty() && !acceptable)
      throw std::invalid_argument("the lat-lon image of the common field would be " + std::to_string(width) + " x " +
                                  std::to_string(height) + " pixels");
    rect.size = options.size.empty() ? cv::Size(int(width), int(height)) : options.size;
    // The box's centre at the image's centre.
    rect.cx = (rect.size.width - 1) / 2.0 - rect.f * 0.5 * (box[0] + box[1]);
    rect.cy = (rect.size.height - 1) / 2.0 - rect.f * 0.5 * (box[2] + box[3]);
  }
  const int n = rect.downscale = options.downscale;
  rect.f /= n;
  rect.cx = (rect.cx + 0.5) / n - 0.5;
  rect.cy = (rect.cy + 0.5) / n - 0.5;
  rect.size = cv::Size((rect.size.width + n - 1) / n, (rect.size.height + n - 1) / n);
  // t = R_right T puts the left camera's centre at (-baseline, 0, 0) of the
  // right rectified frame: the right camera is at (baseline, 0, 0) of the left's.
  const cv::Vec3d t = rect.R_right * cv::Vec3d(rig.T(0), rig.T(1), rig.T(2));
  rect.baseline = -t[0];
  if (!(rect.baseline > 0))
    throw std::invalid_argument("the right camera must be to the right of the left one (T.x < 0)");
  // Z = f b / d for disparity d = u_left - u_right (cv::reprojectImageTo3D's Q).
  if (rect.mode == RectificationMode::kPinhole)
    rect.Q = cv::Matx44d(1, 0, 0, -rect.cx,
                         0, 1, 0, -rect.cy,
                         0, 0, 0, rect.f,
                         0, 0, 1 / rect.baseline, 0);
  return rect;
}

void BuildRectificationMaps(const Rig& rig, Rectification* rect) {
  BuildMaps(Camera(rig.left), rect->R_left, *rect, &rect->maps_left, &rect->valid_left);
  BuildMaps(Camera(rig.right), rect->R_right, *rect, &rect->maps_right, &rect->valid_right);
  rect->no_image = (rect->valid_left == 0) | (rect->valid_right == 0);
  rect->common = cv::boundingRect(rect->no_image == 0);
}

void RectifyPair(const Rectification& rect, const cv::Mat& left, const cv::Mat& right,
                 cv::Mat* left_rect, cv::Mat* right_rect, const cv::Rect& region) {
  Remap(left, rect.maps_left, region, left_rect);
  Remap(right, rect.maps_right, region, right_rect);
}

bool RectifyPoint(const Rectification& rect, const Rig& rig, bool left,
                  const cv::Point2d& pixel, cv::Point2d* rectified) {
  const Camera camera(left ? rig.left : rig.right);
  const auto ray = camera.Unproject(Eigen::Vector2d(pixel.x, pixel.y));
  if (!ray) return false;
  return RectifiedPixel(rect, (left ? rect.R_left : rect.R_right) * cv::Vec3d((*ray)[0], (*ray)[1], (*ray)[2]),
                        rectified);
}

bool RectifiedPixel(const Rectification& rect, const cv::Vec3d& p, cv::Point2d* pixel) {
  if (rect.mode == RectificationMode::kLatLon) {
    const cv::Vec2d a = LatLon(p);
    *pixel = cv::Point2d(rect.f * a[0] + rect.cx, rect.f * a[1] + rect.cy);
    return true;
  }
  if (!(p[2] > 0)) return false;
  *pixel = cv::Point2d(rect.f * p[0] / p[2] + rect.cx, rect.f * p[1] / p[2] + rect.cy);
  return true;
}

cv::Vec3d RectifiedRay(const Rectification& rect, double u, double v) {
  if (rect.mode == RectificationMode::kPinhole) return {(u - rect.cx) / rect.f, (v - rect.cy) / rect.f, 1};
  const double psi = (u - rect.cx) / rect.f, phi = (v - rect.cy) / rect.f;
  return {std::sin(psi), std::cos(psi) * std::sin(phi), std::cos(psi) * std::cos(phi)};
}

cv::Vec3d RectifiedPixelRay(const Rectification& rect, bool left, const cv::Point2d& pixel) {
  return (left ? rect.R_left : rect.R_right).t() * RectifiedRay(rect, pixel.x, pixel.y);
}

cv::Vec2d CommonField(const Rig& rig) {
  cv::Matx33d R_left, R_right;
  BouguetRotations(rig, &R_left, &R_right);
  const cv::Vec4d box = CommonBox(rig, R_left, R_right);
  return {std::max(0.0, box[1] - box[0]), std::max(0.0, box[3] - box[2])};
}

}  // namespace ws
