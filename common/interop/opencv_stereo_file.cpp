#include "interop/opencv_stereo_file.h"

#include <algorithm>
#include <cmath>

#include <opencv2/core/eigen.hpp>

#include "interop/foreign_camera.h"
#include "interop/opencv_lens.h"
#include "rig/rig_file.h"
#include "runtime/atomic_file.h"
#include "runtime/opencv_yaml.h"

namespace ws {
namespace {

cv::Mat Row(const std::vector<double>& values) { return cv::Mat(values, true).reshape(1, 1); }

// The pinhole rectification's projection matrices and the rotations.
void Projections(const Rectification& rect, cv::Mat* P1, cv::Mat* P2) {
  *P1 = (cv::Mat_<double>(3, 4) << rect.f, 0, rect.cx, 0, 0, rect.f, rect.cy, 0, 0, 0, 1, 0);
  *P2 = P1->clone();
  P2->at<double>(0, 3) = -rect.f * rect.baseline;
}

class Reader {
 public:
  explicit Reader(std::string path) : path_(std::move(path)) {}
  [[noreturn]] void Fail(const std::string& field, const std::string& reason) const {
    throw CalibrationFileError(path_ + ": " + field + ": " + reason);
  }
  // A matrix of `rows` x any columns (cols 0) or a given count of values.
  cv::Mat Matrix(const cv::FileNode& root, const std::string& key, int rows, int cols) const {
    const cv::FileNode node = root[key];
    if (node.empty()) Fail(key, "missing");
    if (!node.isMap() || !node["rows"].isInt() || !node["cols"].isInt() || int(node["rows"]) < 1 ||
        int(node["cols"]) < 1 || int(node["rows"]) * int(node["cols"]) > 64)
      Fail(key, "not a small !!opencv-matrix");
    cv::Mat mat;
    try {
      node >> mat;
    } catch (const cv::Exception&) {
      Fail(key, "not an !!opencv-matrix");
    }
    mat.convertTo(mat, CV_64F);
    if (mat.channels() != 1 || (rows && mat.rows != rows) || (cols && mat.cols != cols))
      Fail(key, "not " + std::to_string(rows) + "x" + std::to_string(cols));
    if (!cv::checkRange(mat)) Fail(key, "not finite");
    return mat;
  }
  int Size(const cv::FileNode& root, const std::string& key) const {
    const cv::FileNode node = root[key];
    if (node.empty()) Fail(key, "missing (the image size must be given: image_width, image_height)");
    if (!node.isInt() || int(node) < 1) Fail(key, "not a positive integer");
    return int(node);
  }

 private:
  std::string path_;
};

std::shared_ptr<const CameraProjection> ReadCamera(const Reader& in, const cv::FileNode& root,
                                                   const std::string& k_key, const std::string& d_key,
                                                   bool fisheye, int width, int height) {
  const cv::Mat K = in.Matrix(root, k_key, 3, 3);
  const cv::Mat D = in.Matrix(root, d_key, 0, 0);
  if (K.at<double>(0, 1) != 0 || K.at<double>(1, 0) != 0 || K.at<double>(2, 0) != 0 ||
      K.at<double>(2, 1) != 0 || K.at<double>(2, 2) != 1)
    in.Fail(k_key, "not of the form [fx 0 cx; 0 fy cy; 0 0 1]");
  if (D.rows != 1 && D.cols != 1) in.Fail(d_key, "not a vector");
  std::vector<double> d(D.begin<double>(), D.end<double>());
  CameraModel m;
  m.image_width = width;
  m.image_height = height;
  m.fx = K.at<double>(0, 0), m.fy = K.at<double>(1, 1);
  m.cx = K.at<double>(0, 2), m.cy = K.at<double>(1, 2);
  try {
    if (fisheye) {
      if (d.size() != 4) in.Fail(d_key, "a fisheye D has 4 coefficients");
      m.distortion = Distortion{ModelKind::kKb4, 0, {}, d};
      return std::make_shared<WidestereoProjection>(m);
    }
    if (d.size() == 4 || d.size() == 5) {
      m.distortion = Distortion{ModelKind::kPoly6, 0, {}, {d[0], d[1], d.size() == 5 ? d[4] : 0.0}};
      m.p1 = d[2], m.p2 = d[3];
      return std::make_shared<WidestereoProjection>(m);
    }
    if (d.size() == 14) {  // CALIB_TILTED_MODEL: widestereo's poly6 + tilt when it has no other term
      if (std::any_of(d.begin() + 5, d.begin() + 12, [](double v) { return v != 0; }))
        in.Fail(d_key, "14 coefficients with a rational or thin-prism part (k4 to k6, s1 to s4): only a "
                       "tilted sensor over k1 k2 p1 p2 k3 is read");
      m.distortion = Distortion{ModelKind::kPoly6, 0, {}, {d[0], d[1], d[4]}};
      m.p1 = d[2], m.p2 = d[3];
      m.nonradial.tilt = {d[12], d[13]};
      return std::make_shared<WidestereoProjection>(m);
    }
    if (d.size() != 8 && d.size() != 12)
      in.Fail(d_key, std::to_string(d.size()) + " coefficients: 4, 5, 8, 12 or 14 are read");
    std::vector<double> k{d[0], d[1], d[4], d[5], d[6], d[7], 0, 0, 0, 0};
    if (d.size() == 12) std::copy(d.begin() + 8, d.end(), k.begin() + 6);
    return std::make_shared<ForeignCamera<OpenCvLens>>(
        "opencv " + std::to_string(d.size()) + "-coefficient", width, height, OpenCvLens(),
        std::array<double, kNumIntrinsics>{m.fx, m.fy, m.cx, m.cy, d[2], d[3]}, k);
  } catch (const std::invalid_argument& e) {
    in.Fail(k_key, e.what());
  }
}

}  // namespace

void WriteOpenCvStereoFile(const std::string& path, const Rig& rig, const Rectification& rect,
                           const std::optional<TargetModel> exact[2],
                           const std::vector<std::string>& comments) {
  cv::FileStorage fs(".yaml", cv::FileStorage::WRITE | cv::FileStorage::MEMORY | cv::FileStorage::FORMAT_YAML);
  for (const std::string& line : comments) fs.writeComment(line);
  fs << "image_width" << rig.left.image_width << "image_height" << rig.left.image_height;
  fs << "distortion_model"
     << (exact[0] && exact[1] ? exact[0]->name : "none: widestereo " + ModelName(rig.left.distortion.kind));
  const CameraModel* cameras[2] = {&rig.left, &rig.right};
  for (int i = 0; i < 2; ++i) {
    const CameraModel& m = *cameras[i];
    const std::string n = std::to_string(i + 1);
    fs << "K" + n << cv::Mat(cv::Matx33d(m.fx, 0, m.cx, 0, m.fy, m.cy, 0, 0, 1));
    if (exact[0] && exact[1]) fs << "D" + n << Row(exact[i]->coeffs);
  }
  cv::Mat R, T, P1, P2;
  cv::eigen2cv(rig.R, R);
  cv::eigen2cv(rig.T, T);
  Projections(rect, &P1, &P2);
  fs << "R" << R << "T" << T << "R1" << cv::Mat(rect.R_left) << "R2" << cv::Mat(rect.R_right)
     << "P1" << P1 << "P2" << P2 << "Q" << cv::Mat(rect.Q);
  fs << "rectified_width" << rect.size.width << "rectified_height" << rect.size.height;
  WriteFileAtomically(path, fs.releaseAndGetString());
}

void WriteRectificationMaps(const std::string& path, const Rectification& rect) {
  cv::FileStorage fs(".yaml", cv::FileStorage::WRITE | cv::FileStorage::MEMORY | cv::FileStorage::FORMAT_YAML);
  fs.writeComment("cv::remap(image, rectified, map1, map2, cv::INTER_LINEAR, cv::BORDER_CONSTANT)");
  fs << "map1_left" << rect.maps_left.front()[0] << "map2_left" << rect.maps_left.front()[1];
  fs << "map1_right" << rect.maps_right.front()[0] << "map2_right" << rect.maps_right.front()[1];
  WriteFileAtomically(path, fs.releaseAndGetString());
}

AnyRig ReadOpenCvCalibration(const std::string& path) {
  const Reader in(path);
  cv::FileStorage fs;
  try {
    OpenOpenCvYaml(fs, path);
  } catch (const YamlFileError& e) {
    in.Fail("(file)", e.what());
  }
  const cv::FileNode root = fs.root();
  if (!root.isMap()) in.Fail("(file)", "not a map of fields");
  const int width = in.Size(root, "image_width"), height = in.Size(root, "image_height");
  std::string model = "pinhole";
  if (!root["distortion_model"].empty()) {
    if (!root["distortion_model"].isString()) in.Fail("distortion_model", "not a string");
    model = std::string(root["distortion_model"]);
  }
  if (model != "pinhole" && model != "fisheye")
    in.Fail("distortion_model", "'" + model + "': pinhole or fisheye (a camera OpenCV has no model "
                                "of is exported as its maps: compare the widestereo file itself)");
  AnyRig rig;
  rig.format = "opencv";
  const bool fisheye = model == "fisheye";
  if (!root["camera_matrix"].empty()) {
    rig.mono = true;
    rig.left = ReadCamera(in, root, "camera_matrix", "distortion_coefficients", fisheye, width, height);
    return rig;
  }
  const std::string k = root["K1"].empty() && !root["M1"].empty() ? "M" : "K";
  rig.left = ReadCamera(in, root, k + "1", "D1", fisheye, width, height);
  rig.right = ReadCamera(in, root, k + "2", "D2", fisheye, width, height);
  cv::cv2eigen(in.Matrix(root, "R", 3, 3), rig.R);
  cv::cv2eigen(in.Matrix(root, "T", 3, 1), rig.T);
  if (!IsRotation(rig.R))
    in.Fail("R", "not a rotation");
  return rig;
}

}  // namespace ws
