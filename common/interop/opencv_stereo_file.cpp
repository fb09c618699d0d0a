#include "interop/opencv_stereo_file.h"

#include <algorithm>
#include <cmath>

#include <opencv2/core/eigen.hpp>

#include "interop/foreign_camera.h"
#include "interop/opencv_lens.h"
#include "rig/camera_fields.h"
#include "rig/rig_file.h"
#include "rig/yaml_reader.h"
#include "runtime/atomic_file.h"
#include "runtime/opencv_yaml.h"

namespace ws {
namespace {

constexpr const char* kNoOpenCvModel = "none: widestereo";

cv::Mat Row(const std::vector<double>& values) { return cv::Mat(values, true).reshape(1, 1); }

// The pinhole rectification's projection matrices and the rotations.
void Projections(const Rectification& rect, cv::Mat* P1, cv::Mat* P2) {
  *P1 = (cv::Mat_<double>(3, 4) << rect.f, 0, rect.cx, 0, 0, rect.f, rect.cy, 0, 0, 0, 1, 0);
  *P2 = P1->clone();
  P2->at<double>(0, 3) = -rect.f * rect.baseline;
}

// A camera's image size: its own "missing" says which field OpenCV's
// calibration files leave out.
int ImageSize(const YamlReader& in, const cv::FileNode& root, const std::string& key) {
  if (root[key].empty()) in.Fail(key, "missing (the image size must be given: image_width, image_height)");
  return in.Int(root, key, key, 1);
}

std::shared_ptr<const CameraProjection> ReadCamera(const YamlReader& in, const cv::FileNode& root,
                                                   const std::string& k_key, const std::string& d_key,
                                                   bool fisheye, int width, int height) {
  CameraModel m;
  m.image_width = width;
  m.image_height = height;
  ReadCameraMatrix(in, root, k_key, k_key, &m);
  // At most OpenCV's longest D, CALIB_TILTED_MODEL's 14.
  const std::vector<double> d = in.Reals(root, d_key, d_key, 14);
  try {
    if (fisheye) {
      if (d.size() != 4) in.Fail(d_key, "a fisheye D has 4 coefficients");
      m.distortion = Distortion{ModelKind::kKb4, 0, {}, d};
      return std::make_shared<WidestereoProjection>(m);
    }
    if (OpenCvPoly6(d, &m)) return std::make_shared<WidestereoProjection>(m);
    if (d.size() == 14)  // CALIB_TILTED_MODEL: widestereo's poly6 + tilt when it has no other term
      in.Fail(d_key, "14 coefficients with a rational or thin-prism part (k4 to k6, s1 to s4): only a "
                     "tilted sensor over k1 k2 p1 p2 k3 is read");
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

// stereo-export's file of cameras OpenCV has no model of: the rectified
// pair its maps make, pinhole cameras of P1 and P2 without distortion in the
// rectified image, side by side (R = I), the right one at P2's x
// translation -f baseline.
AnyRig RectifiedPair(const YamlReader& in, const cv::FileNode& root) {
  const Eigen::MatrixXd P[2] = {in.Matrix(root, "P1", "P1", 3, 4), in.Matrix(root, "P2", "P2", 3, 4)};
  CameraModel m;
  m.image_width = ImageSize(in, root, "rectified_width");
  m.image_height = ImageSize(in, root, "rectified_height");
  m.distortion = Distortion{ModelKind::kPoly6, 0, {}, {0, 0, 0}};
  AnyRig rig;
  rig.format = "opencv";
  for (int i = 0; i < 2; ++i) {
    const Eigen::MatrixXd& p = P[i];
    if (p(0, 1) != 0 || p(1, 0) != 0 || p(2, 0) != 0 || p(2, 1) != 0 || p(2, 2) != 1 || p(1, 3) != 0 ||
        p(2, 3) != 0 || p(0, 0) != P[0](0, 0))
      in.Fail(i == 0 ? "P1" : "P2", "not a rectified pinhole camera [f 0 cx tx; 0 f cy 0; 0 0 1 0]");
    m.fx = p(0, 0), m.fy = p(1, 1), m.cx = p(0, 2), m.cy = p(1, 2);
    try {
      (i == 0 ? rig.left : rig.right) = std::make_shared<WidestereoProjection>(m);
    } catch (const std::invalid_argument& e) {
      in.Fail(i == 0 ? "P1" : "P2", e.what());
    }
  }
  rig.T = Eigen::Vector3d(P[1](0, 3) / m.fx, 0, 0);
  if (rig.T.x() == 0) in.Fail("P2", "no baseline (P2's x translation is 0)");
  return rig;
}

}  // namespace

void WriteOpenCvStereoFile(const std::string& path, const Rig& rig, const Rectification& rect,
                           const std::optional<TargetModel> exact[2],
                           const std::vector<std::string>& comments) {
  cv::FileStorage fs(".yaml", cv::FileStorage::WRITE | cv::FileStorage::MEMORY | cv::FileStorage::FORMAT_YAML);
  for (const std::string& line : comments) fs.writeComment(line);
  fs << "image_width" << rig.left.image_width << "image_height" << rig.left.image_height;
  fs << "distortion_model"
     << (exact[0] && exact[1] ? exact[0]->name : kNoOpenCvModel + (" " + ModelName(rig.left.distortion.kind)));
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
  const YamlReader in(path, "with stereo-export or OpenCV's cv::FileStorage");
  cv::FileStorage fs;
  const cv::FileNode root = in.Open(fs, kMaxYamlFileBytes);
  const int width = ImageSize(in, root, "image_width"), height = ImageSize(in, root, "image_height");
  std::string model = "pinhole";
  if (!root["distortion_model"].empty()) {
    if (!root["distortion_model"].isString()) in.Fail("distortion_model", "not a string");
    model = std::string(root["distortion_model"]);
  }
  AnyRig rig;
  rig.format = "opencv";
  if (model.rfind(kNoOpenCvModel, 0) == 0) return RectifiedPair(in, root);
  if (model != "pinhole" && model != "fisheye")
    in.Fail("distortion_model", "'" + model + "': pinhole, fisheye or '" + kNoOpenCvModel + " MODEL'");
  const bool fisheye = model == "fisheye";
  if (!root["camera_matrix"].empty()) {
    rig.mono = true;
    rig.left = ReadCamera(in, root, "camera_matrix", "distortion_coefficients", fisheye, width, height);
    return rig;
  }
  const std::string k = root["K1"].empty() && !root["M1"].empty() ? "M" : "K";
  rig.left = ReadCamera(in, root, k + "1", "D1", fisheye, width, height);
  rig.right = ReadCamera(in, root, k + "2", "D2", fisheye, width, height);
  rig.R = in.Matrix(root, "R", "R", 3, 3);
  rig.T = in.Matrix(root, "T", "T", 3, 1);
  if (!IsRotation(rig.R))
    in.Fail("R", "not a rotation");
  return rig;
}

}  // namespace ws
