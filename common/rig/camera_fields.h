// A camera's fields in a YAML file, written and read in one place: the
// calibration file's `left:` and `right:` maps (rig/rig_file.h) and the
// simulator's truth (sim/ground_truth.h) hold a camera so.
//
//   image_width: 1280
//   image_height: 960
//   camera_matrix: !!opencv-matrix   3x3, [fx 0 cx; 0 fy cy; 0 0 1]
//   model: bspline                   a model's name (models/model_registry.h)
//   degree: 3                        B-spline degree (0 for the polynomials)
//   knots: !!opencv-matrix           1 x N, the clamped knot vector (the splines only)
//   alpha: !!opencv-matrix           1 x N, the coefficients under the model's key (alpha or k)
//   p1: ...                          tangential distortion
//   p2: ...
//   nonradial: {cols, rows, domain, coeffs, tilt}   when the camera has a field or a tilt
#pragma once

#include <string>

#include <opencv2/core.hpp>

#include "models/camera_model.h"
#include "rig/yaml_reader.h"

namespace ws {

// Writes the fields above into the map open in `fs`.
void WriteCameraFields(cv::FileStorage& fs, const CameraModel& m);

// Reads and checks them from the map `node` (`at`: its name in messages,
// e.g. "left."): the model's knots and coefficients agree, K of the pinhole
// form with positive focal lengths, a field of at most 64 control points a
// side. Throws YamlFieldError.
CameraModel ReadCameraFields(const YamlReader& in, const cv::FileNode& node, const std::string& at);

// fx, fy, cx, cy from the 3 x 3 camera matrix under `key` (`field` in
// messages), of the form [fx 0 cx; 0 fy cy; 0 0 1] with positive focal
// lengths (OpenCV's K, as the calibration file and OpenCV's own files hold
// it). Throws YamlFieldError.
void ReadCameraMatrix(const YamlReader& in, const cv::FileNode& node, const std::string& key, const std::string& field,
                      CameraModel* m);

// The model kind named by node's "model" (`field` in messages).
ModelKind ReadModelKind(const YamlReader& in, const cv::FileNode& node, const std::string& field);

}  // namespace ws
