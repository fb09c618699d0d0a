#include "interop/any_rig.h"

#include <Eigen/LU>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "interop/kalibr_camchain.h"
#include "interop/mrcal_cameramodel.h"
#include "interop/opencv_stereo_file.h"
#include "interop/ros_camera_info.h"
#include "rig/rig_file.h"
#include "runtime/bounded_file.h"
#include "runtime/opencv_yaml.h"

namespace ws {
namespace {

// Whether a file has a line starting with `prefix` ("key:" for a YAML
// file's top-level key).
bool HasLineStartingWith(const std::string& path, const std::string& prefix) {
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line))
    if (line.rfind(prefix, 0) == 0) return true;
  return false;
}

AnyRig FromCalibrationFile(const std::string& path) {
  const Rig file = ReadCalibrationFile(path);
  AnyRig rig;
  rig.format = "widestereo";
  rig.mono = file.mono;
  rig.left = std::make_shared<WidestereoProjection>(file.left);
  if (!file.mono) rig.right = std::make_shared<WidestereoProjection>(file.right);
  rig.R = file.R;
  rig.T = file.T;
  return rig;
}

AnyRig FromMrcal(const std::string& path) {
  AnyRig rig;
  rig.format = "mrcal";
  if (!std::filesystem::is_directory(path)) {
    rig.mono = true;
    rig.left = MrcalCamera(ReadMrcalCameraModel(path));
    return rig;
  }
  const std::string left_path = path + "/camera-0.cameramodel", right_path = path + "/camera-1.cameramodel";
  if (!std::filesystem::exists(left_path))
    throw CalibrationFileError(path + ": camera-0.cameramodel: missing (a folder is read as "
                                      "mrcal-calibrate-cameras' output, or stereo-export's: camera-0.cameramodel, "
                                      "left.yaml, stereo.yaml or camchain.yaml)");
  const MrcalCameraModel left = ReadMrcalCameraModel(left_path);
  rig.left = MrcalCamera(left);
  rig.mono = !std::filesystem::exists(right_path);
  if (rig.mono) return rig;
  const MrcalCameraModel right = ReadMrcalCameraModel(right_path);
  rig.right = MrcalCamera(right);
  MrcalRelativePose(left, right, &rig.R, &rig.T);
  return rig;
}

// One camera_info file: a one-camera rig.
AnyRig FromRos(const std::string& path) {
  AnyRig rig;
  rig.format = "ros";
  rig.mono = true;
  rig.left = std::make_shared<WidestereoProjection>(RosCameraModel(ReadRosCameraInfo(path), path));
  return rig;
}

// A folder of left.yaml and right.yaml (what stereo-export --format ros
// writes): each camera rotated by its rectification_matrix R1, R2 into a
// common rectified frame, in which the right one sits at t = (P[0][3] / P[0][0],
// P[1][3] / P[1][1], P[2][3]) (ROS: Tx = -fx' B). So X_right = R2^T (R1 X_left + t).
AnyRig FromRosPair(const std::string& folder) {
  const std::string left_path = folder + "/left.yaml", right_path = folder + "/right.yaml";
  const RosCameraInfo left = ReadRosCameraInfo(left_path), right = ReadRosCameraInfo(right_path);
  AnyRig rig;
  rig.format = "ros";
  rig.left = std::make_shared<WidestereoProjection>(RosCameraModel(left, left_path));
  rig.right = std::make_shared<WidestereoProjection>(RosCameraModel(right, right_path));
  Eigen::Matrix3d R1, R2;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) R1(r, c) = left.R(r, c), R2(r, c) = right.R(r, c);
  for (const auto& [R, path] : {std::pair{&R1, &left_path}, std::pair{&R2, &right_path}})
    if (!IsRotation(*R)) throw CalibrationFileError(*path + ": rectification_matrix: not a rotation");
  const cv::Matx34d& P = right.P;
  if (!(P(0, 0) > 0) || !(P(1, 1) > 0))
    throw CalibrationFileError(right_path + ": projection_matrix: focal lengths not positive");
  const Eigen::Vector3d t(P(0, 3) / P(0, 0), P(1, 3) / P(1, 1), P(2, 3));
  rig.R = R2.transpose() * R1;
  rig.T = R2.transpose() * t;
  if (rig.T.norm() == 0)
    throw CalibrationFileError(right_path + ": projection_matrix: no baseline (Tx = 0): not the right camera "
                                            "of a pair");
  return rig;
}

// A folder: mrcal-calibrate-cameras' (camera-0.cameramodel) or any that
// stereo-export writes: mrcal's, ROS's (left.yaml and right.yaml; left.yaml
// alone of one camera), OpenCV's (stereo.yaml) or Kalibr's (camchain.yaml).
AnyRig FromFolder(const std::string& folder) {
  const auto has = [&](const char* name) { return std::filesystem::exists(folder + "/" + name); };
  if (has("camera-0.cameramodel")) return FromMrcal(folder);
  if (has("left.yaml") && has("right.yaml")) return FromRosPair(folder);
  if (has("left.yaml")) return FromRos(folder + "/left.yaml");
  if (has("stereo.yaml")) return ReadOpenCvCalibration(folder + "/stereo.yaml");
  if (has("camchain.yaml")) return ReadKalibrCamchain(folder + "/camchain.yaml");
  return FromMrcal(folder);  // says what it missed
}

}  // namespace

Rig AnyRig::AsStereoRig() const {
  if (mono) throw std::invalid_argument("a one-camera calibration is not a stereo rig");
  Rig rig;
  for (const auto& [camera, model] : {std::pair{left.get(), &rig.left}, std::pair{right.get(), &rig.right}}) {
    if (!camera->AsCamera())
      throw std::invalid_argument("the camera model " + camera->Name() +
                                  " is not one of widestereo's: it can be compared, not rectified");
    *model = camera->AsCamera()->model();
  }
  rig.R = R;
  rig.T = T;
  return rig;
}

bool IsRotation(const Eigen::Matrix3d& R) {
  return (R.transpose() * R).isApprox(Eigen::Matrix3d::Identity(), 1e-6) && R.determinant() > 0;
}

AnyRig LoadAnyRig(const std::string& path) {
  const std::filesystem::path p(path);
  if (!std::filesystem::exists(p)) throw CalibrationFileError(path + ": (file): missing");
  std::error_code error;
  if (std::filesystem::is_directory(p, error)) return FromFolder(path);
  // Checked before the format is sniffed: no calibration of any format is
  // larger than the largest file any of the readers takes, and each reader
  // checks its own file again.
  static_assert(kMaxCameraModelBytes <= kMaxYamlFileBytes);
  try {
    RequireBoundedFile(path, kMaxYamlFileBytes);
  } catch (const BoundedFileError& e) {
    throw CalibrationFileError(path + ": (file): " + e.what());
  }
  if (p.extension() == ".cameramodel") return FromMrcal(path);
  if (HasLineStartingWith(path, "cam0:")) return ReadKalibrCamchain(path);
  if (HasLineStartingWith(path, "distortion_model:") && HasLineStartingWith(path, "projection_matrix:"))
    return FromRos(path);
  // widestereo's own: its header, or (a file edited by hand) its keys; a
  // file of ours cut short is then refused by our reader, saying so.
  if (HasLineStartingWith(path, std::string("# ") + kCalibrationFileTitle) ||
      (HasLineStartingWith(path, "left:") && HasLineStartingWith(path, "model:")))
    return FromCalibrationFile(path);
  return ReadOpenCvCalibration(path);
}

}  // namespace ws
