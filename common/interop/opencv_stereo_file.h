// OpenCV's calibration YAML (cv::FileStorage), both ways.
//
// stereo-export --to opencv-stereo writes OUT/stereo.yaml:
//   image_width, image_height             the input images
//   distortion_model     "pinhole" (cv::calibrateCamera's model, D 5
//       coefficients k1 k2 p1 p2 k3), "fisheye" (cv::fisheye, D k1..k4), or
//       "none: widestereo MODEL" when OpenCV has no model of the cameras
//       (exact_model.h): then K and no D, and the maps are the cameras
//   K1, D1, K2, D2, R, T                  X_right = R X_left + T
//   R1, R2, P1, P2, Q                     the pinhole rectification, as
//       cv::stereoRectify returns them (Bouguet's rotations; P2's x
//       translation -f baseline; Q for cv::reprojectImageTo3D)
//   rectified_width, rectified_height
// and OUT/maps.yml.gz: map1_left, map2_left, map1_right, map2_right, the
// fixed-point tables of cv::remap(image, out, map1, map2, INTER_LINEAR),
// the very ones stereo-match rectifies with.
//
// For comparison it reads OpenCV calibration YAML: K1 D1 K2 D2 R T (or
// stereo_calib's M1 D1 M2 D2 R T) of a pair, camera_matrix and
// distortion_coefficients of one camera, with image_width and image_height
// and, optionally, distortion_model (pinhole, the default, or fisheye). D
// of 4 or 5 coefficients is widestereo's poly6; 8 or 12 OpenCV's rational
// and thin prism model (opencv_lens.h); 14 (CALIB_TILTED_MODEL) poly6 with
// its sensor tilt when no rational or thin-prism term is set. A stereo.yaml
// of cameras OpenCV has no model of ("none: widestereo MODEL", no D) reads
// as the rectified pair its maps make: pinhole cameras of P1 and P2 in the
// rectified image, R = I, T = (P2's x translation / f, 0, 0).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "interop/any_rig.h"
#include "interop/exact_model.h"
#include "rectify/rectification.h"

namespace ws {

// Writes stereo.yaml as above; exact[i] is camera i's OpenCV model, when it
// has one (D only when both have). Throws std::runtime_error when it cannot.
void WriteOpenCvStereoFile(const std::string& path, const Rig& rig, const Rectification& rect,
                           const std::optional<TargetModel> exact[2],
                           const std::vector<std::string>& comments);

// Writes both cameras' fixed-point remap tables (a .gz path: compressed).
void WriteRectificationMaps(const std::string& path, const Rectification& rect);

// Throws CalibrationFileError "FILE: FIELD: REASON".
AnyRig ReadOpenCvCalibration(const std::string& path);

}  // namespace ws
