// The calibration file (stereo-calibrate --out): the rig (rig/rig.h) as YAML
// that OpenCV's cv::FileStorage reads directly, with the camera model defined in the
// docs/models.md and repeated in the file's header comment.
//
//   cv::FileStorage fs("calib.yaml", cv::FileStorage::READ);
//   cv::Mat K, R, T;
//   fs["left"]["camera_matrix"] >> K;
//   fs["stereo"]["R"] >> R;  fs["stereo"]["T"] >> T;
//
// Layout:
//
//   model: bspline                     the kind of both cameras' models
//   left:                              (and right:, the same keys)
//     image_width: 1280
//     image_height: 960
//     camera_matrix: !!opencv-matrix   3x3, [fx 0 cx; 0 fy cy; 0 0 1]
//     model: bspline                   bspline | poly6 | poly12
//     degree: 3                        B-spline degree (0 for the polynomials)
//     knots: [ ... ]                   the clamped knot vector (bspline only)
//     alpha: [ ... ]                   every alpha_i, alpha_0 = alpha_1 = 0 included (bspline)
//     k: [ ... ]                       k1..k3 (poly6) or k1..k6 (poly12), instead of alpha
//     p1: ...                          tangential distortion
//     p2: ...
//     rms: ...                         reprojection RMS, pixels
//     views: ...                       views used
//   stereo:
//     R: !!opencv-matrix               3x3 rotation, X_right = R X_left + T
//     T: !!opencv-matrix               3x1, metres
//     rms: ...                         stereo reprojection RMS, pixels
//     baseline_m: ...                  |T|
//     views: ...                       stereo views used
#pragma once

#include <string>

#include "rig/rig.h"
#include "rig/yaml_reader.h"

namespace ws {

// The first words of the comment that opens every file WriteCalibrationFile
// writes: how a reader tells our file from a foreign one (interop/any_rig.h).
inline constexpr char kCalibrationFileTitle[] = "widestereo stereo calibration";

// What ReadCalibrationFile throws: "FILE: FIELD: REASON", e.g.
// "calib.yaml: left.camera_matrix: not a 3x3 matrix" (rig/yaml_reader.h).
using CalibrationFileError = YamlFieldError;

// Writes the file (to a temporary beside it, then renamed, so a reader never
// sees half a file). Throws std::runtime_error when it cannot.
void WriteCalibrationFile(const std::string& path, const Rig& rig);

// Reads a calibration file and checks every field: present, of its type,
// finite, in range (positive sizes and focal lengths, K of the pinhole form,
// a known model whose knots and coefficients agree, R a rotation, baseline_m
// equal to |T|, both cameras of the file's model). Throws
// CalibrationFileError naming the file, the field and the reason.
Rig ReadCalibrationFile(const std::string& path);

// The same, for a stereo rig: throws CalibrationFileError for a one-camera
// file too.
Rig StereoRigFromFile(const std::string& path);

}  // namespace ws
