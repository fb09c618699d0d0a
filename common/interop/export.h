// stereo-export: a widestereo calibration in another tool's format, written
// into a folder (docs/export.md):
//
//   opencv-stereo  stereo.yaml (K D R T R1 R2 P1 P2 Q) and maps.yml.gz, the
//                  pinhole rectification's remap tables (opencv_stereo_file.h)
//   ros            left.yaml, right.yaml: camera_info (ros_camera_info.h);
//                  for a model ROS has not, the rectified cameras, with
//                  maps.yml.gz to rectify the raw images by first
//   kalibr         camchain.yaml (kalibr_camchain.h); for a model Kalibr has
//                  not, the closest pinhole-equi or pinhole-radtan (model_fit.h)
//   mrcal          camera-0.cameramodel, camera-1.cameramodel
//                  (mrcal_cameramodel.h); for a model mrcal has not, a
//                  fitted LENSMODEL_SPLINED_STEREOGRAPHIC (mrcal_spline_fit.h)
//
// Exact where the format has the camera's model (exact_model.h); otherwise
// the export says so, in the files and in its report, with the error of
// what it wrote instead.
#pragma once

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "interop/exact_model.h"
#include "rig/rig_file.h"

namespace ws {

struct ExportReport {
  std::vector<std::string> files;  // written, in `out`
  std::vector<std::string> lines;  // what each camera became, and its error
  bool exact = true;               // every camera as the format's own model
  double max_error_px = 0;         // the largest error printed (0 when exact)
};

// observed_radius: each camera's outermost calibrated corner
// (CalibrationReportRadii), bounding the lens circle a fitted mrcal spline
// is fitted within; infinite when unknown. mrcal_nx > 0: the spline's knots
// across, instead of the first grid within 0.01 px (mrcal_spline_fit.h).
// Creates `out` when missing.
// Throws std::invalid_argument when the format cannot hold the calibration
// at all (a one-camera file has no stereo rectification) and
// std::runtime_error when a file cannot be written.
ExportReport ExportCalibration(const Rig& file, ExportFormat format, const std::string& out,
                               const std::array<double, 2>& observed_radius = {INFINITY, INFINITY},
                               int mrcal_nx = 0);

// Each camera's max_observed_radius from the calibration's report
// (stereo-calibrate --report, or NAME.report.json beside --out): the entry
// of the file's model, whose fx must be the file's. Throws
// std::runtime_error naming the report for a report that is not the file's.
std::array<double, 2> CalibrationReportRadii(const std::string& report, const Rig& file);

}  // namespace ws
