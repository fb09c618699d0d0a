#include "calib/calib_file.h"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include <opencv2/core.hpp>

namespace ws::calib {
namespace {

const char* kHeader[] = {
    "widestereo stereo calibration (docs/calibration.md). Pixel of a camera-frame point (X,Y,Z):",
    "  x = X/Z, y = Y/Z, r = sqrt(x^2 + y^2)",
    "  xd = (1 + D(r)) x + 2 p1 x y + p2 (r^2 + 2 x^2)",
    "  yd = (1 + D(r)) y + p1 (r^2 + 2 y^2) + 2 p2 x y",
    "  u = fx xd + cx,  v = fy yd + cy   (pixel centres at integer coordinates, as in OpenCV)",
    "D(r): bspline: sum_i alpha_i N_{i,degree}(r), the de Boor-Cox B-spline basis on 'knots'",
    "      (clamped; beyond the last knot the last polynomial piece continues);",
    "      poly6: k1 r^2 + k2 r^4 + k3 r^6; poly12: k1 r^2 + ... + k6 r^12.",
    "Stereo: X_right = R X_left + T (metres)."};

void WriteCamera(cv::FileStorage& fs, const std::string& name, const CameraModel& m, double rms,
                 int views) {
  fs << name << "{";
  fs << "image_width" << m.image_width << "image_height" << m.image_height;
  const cv::Matx33d K(m.fx, 0, m.cx, 0, m.fy, m.cy, 0, 0, 1);
  fs << "camera_matrix" << cv::Mat(K);
  fs << "model" << m.distortion.kind << "degree" << m.distortion.degree;
  if (m.distortion.kind == "bspline") {
    fs << "knots" << m.distortion.knots;
    fs << "alpha" << m.distortion.coeffs;
  } else {
    fs << "k" << m.distortion.coeffs;
  }
  fs << "p1" << m.p1 << "p2" << m.p2 << "rms" << rms << "views" << views;
  fs << "}";
}

[[noreturn]] void Fail(const std::string& path, const std::string& what) {
  throw std::runtime_error(path + ": " + what);
}

CameraModel ReadCamera(const cv::FileNode& node, const std::string& path, const std::string& name,
                       double* rms, int* views) {
  if (node.empty() || !node.isMap()) Fail(path, "no '" + name + "' camera");
  CameraModel m;
  node["image_width"] >> m.image_width;
  node["image_height"] >> m.image_height;
  cv::Mat K;
  node["camera_matrix"] >> K;
  if (K.rows != 3 || K.cols != 3) Fail(path, name + ".camera_matrix is not 3x3");
  K.convertTo(K, CV_64F);
  m.fx = K.at<double>(0, 0);
  m.fy = K.at<double>(1, 1);
  m.cx = K.at<double>(0, 2);
  m.cy = K.at<double>(1, 2);
  node["model"] >> m.distortion.kind;
  node["degree"] >> m.distortion.degree;
  if (m.distortion.kind == "bspline") {
    node["knots"] >> m.distortion.knots;
    node["alpha"] >> m.distortion.coeffs;
  } else {
    node["k"] >> m.distortion.coeffs;
  }
  node["p1"] >> m.p1;
  node["p2"] >> m.p2;
  node["rms"] >> *rms;
  node["views"] >> *views;
  try {
    const Camera check(m);  // validates sizes, intrinsics, knots and coefficients
  } catch (const std::exception& e) {
    Fail(path, name + ": " + e.what());
  }
  return m;
}

}  // namespace

CalibrationFile ToCalibrationFile(const StereoCalibration& c) {
  CalibrationFile f;
  f.model = c.model;
  f.left = c.left.model;
  f.right = c.right.model;
  f.left_rms = c.left.rms_px;
  f.right_rms = c.right.rms_px;
  f.left_views = c.left.views;
  f.right_views = c.right.views;
  f.R = c.R;
  f.T = c.T;
  f.rms = c.rms_px;
  f.views = c.views;
  return f;
}

void WriteCalibrationFile(const std::string& path, const CalibrationFile& file) {
  const std::string tmp = path + ".tmp";
  {
    cv::FileStorage fs(tmp, cv::FileStorage::WRITE | cv::FileStorage::FORMAT_YAML);
    if (!fs.isOpened()) throw std::runtime_error("cannot write " + path);
    for (const char* line : kHeader) fs.writeComment(line);
    fs << "model" << file.model;
    WriteCamera(fs, "left", file.left, file.left_rms, file.left_views);
    WriteCamera(fs, "right", file.right, file.right_rms, file.right_views);
    fs << "stereo" << "{";
    cv::Mat R(3, 3, CV_64F), T(3, 1, CV_64F);
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) R.at<double>(r, c) = file.R(r, c);
      T.at<double>(r) = file.T(r);
    }
    fs << "R" << R << "T" << T << "rms" << file.rms << "baseline_m" << file.T.norm() << "views"
       << file.views;
    fs << "}";
    fs.release();
  }
  std::error_code error;
  std::filesystem::rename(tmp, path, error);
  if (error) throw std::runtime_error("cannot write " + path + ": " + error.message());
}

CalibrationFile ReadCalibrationFile(const std::string& path) {
  cv::FileStorage fs;
  try {
    if (!fs.open(path, cv::FileStorage::READ)) Fail(path, "cannot open");
  } catch (const cv::Exception& e) {
    Fail(path, std::string("not a calibration file: ") + e.what());
  }
  CalibrationFile f;
  fs["model"] >> f.model;
  f.left = ReadCamera(fs["left"], path, "left", &f.left_rms, &f.left_views);
  f.right = ReadCamera(fs["right"], path, "right", &f.right_rms, &f.right_views);
  const cv::FileNode stereo = fs["stereo"];
  if (stereo.empty()) Fail(path, "no 'stereo' section");
  cv::Mat R, T;
  stereo["R"] >> R;
  stereo["T"] >> T;
  if (R.rows != 3 || R.cols != 3 || T.total() != 3) Fail(path, "stereo R must be 3x3 and T 3x1");
  R.convertTo(R, CV_64F);
  T.convertTo(T, CV_64F);
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) f.R(r, c) = R.at<double>(r, c);
    f.T(r) = T.at<double>(r);
  }
  if (!f.R.allFinite() || !f.T.allFinite()) Fail(path, "non-finite R or T");
  stereo["rms"] >> f.rms;
  stereo["views"] >> f.views;
  return f;
}

}  // namespace ws::calib
