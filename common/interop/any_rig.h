// A calibration of one camera or a stereo pair made by any tool widestereo
// reads, for comparing it with another (stereo-compare) and using it from
// Python:
//
//   widestereo  the calibration file (rig/rig_file.h)
//   mrcal       a .cameramodel (one camera), or a folder holding
//               camera-0.cameramodel and camera-1.cameramodel (a pair, as
//               mrcal-calibrate-cameras writes them)          mrcal_cameramodel.h
//   kalibr      a camchain YAML (cam0, cam1: pinhole with radtan or
//               equidistant distortion)                        kalibr_camchain.h
//   opencv      an OpenCV calibration YAML (cv::FileStorage: K1 D1 K2 D2 R
//               T or M1 D1 M2 D2 R T of a pair, camera_matrix
//               distortion_coefficients of one camera; image_width and
//               image_height; distortion_model pinhole or fisheye) opencv_stereo_file.h
//   ros         a camera_info YAML (one camera: plumb_bob, equidistant or
//               rational_polynomial of OpenCV's tilted model),
//               or a folder of left.yaml and right.yaml (a pair, as
//               stereo-export --format ros writes them)   ros_camera_info.h
//
// stereo-export's output folder of each reads too (any of its formats, a
// camera OpenCV or ROS has no model of as the rectified pair its maps make).
//
// The format is told by the path: a folder by the file it holds
// (camera-0.cameramodel: mrcal's; left.yaml: ROS's, a pair with
// right.yaml; stereo.yaml: OpenCV's; camchain.yaml: Kalibr's);
// *.cameramodel is mrcal's; a YAML file is Kalibr's when it has cam0, ROS's
// when it has distortion_model and projection_matrix, widestereo's when it
// has left and model, OpenCV's otherwise.
#pragma once

#include <memory>
#include <string>

#include <Eigen/Core>

#include "interop/camera_projection.h"
#include "rig/rig.h"

namespace ws {

struct AnyRig {
  std::string format;  // "widestereo", "mrcal", "kalibr", "opencv", "ros"
  bool mono = false;   // one camera: left only
  std::shared_ptr<const CameraProjection> left, right;
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();  // X_right = R X_left + T
  Eigen::Vector3d T = Eigen::Vector3d::Zero();      // metres (the tool's unit)

  // The rig as widestereo's models, for rectifying and exporting. Throws
  // std::invalid_argument naming the camera that is another tool's model
  // (mrcal's spline, OpenCV's rational model), and for a one-camera rig.
  Rig AsStereoRig() const;
};

// Whether R is a rotation (R^T R = I to 1e-6, det R > 0): what the readers
// require of a file's R.
bool IsRotation(const Eigen::Matrix3d& R);

// Reads any of the formats above. Throws CalibrationFileError
// "FILE: FIELD: REASON".
AnyRig LoadAnyRig(const std::string& path);

}  // namespace ws
