// mrcal's camera model file (.cameramodel, mrcal 2.2): a Python dict
//
//   { 'lensmodel': 'LENSMODEL_OPENCV8',
//     'intrinsics': [ fx, fy, cx, cy, distortion... ],
//     'extrinsics': [ rx, ry, rz, tx, ty, tz ],   rt_fromref: X_cam = R(r) X_ref + t
//     'imagersize': [ width, height ], ... }
//
// read (the other keys, e.g. optimization_inputs, are skipped) and written;
// and the camera it describes, for the lens models mrcal 2.2 evaluates that
// widestereo reads: LENSMODEL_PINHOLE and OPENCV4/5 are widestereo's poly6
// exactly; OPENCV8/12 are OpenCV's rational model (opencv_lens.h) and
// SPLINED_STEREOGRAPHIC_order=3 mrcal's spline (mrcal_spline.h), both
// evaluated here.
#pragma once

#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "interop/camera_projection.h"

namespace ws {

struct MrcalCameraModel {
  std::string lensmodel;
  std::vector<double> intrinsics;  // fx, fy, cx, cy, then the lens model's own
  std::array<double, 6> extrinsics{};  // rt_fromref
  int width = 0, height = 0;
};

// The largest .cameramodel read (runtime/bounded_file.h): mrcal's own files,
// optimization_inputs and all, are about a megabyte.
constexpr size_t kMaxCameraModelBytes = size_t(64) << 20;

// Throws CalibrationFileError "FILE: FIELD: REASON" for a file that is
// not one (not a regular file of at most kMaxCameraModelBytes included), a
// missing field, a wrong count or a number that is not finite.
MrcalCameraModel ReadMrcalCameraModel(const std::string& path);

// Writes the file with every number at full precision, `comments` first as
// # lines. Throws std::runtime_error when it cannot.
void WriteMrcalCameraModel(const std::string& path, const MrcalCameraModel& model,
                           const std::vector<std::string>& comments);

// The camera of the model. Throws std::invalid_argument for a lens model
// widestereo does not read or intrinsics of the wrong count.
std::shared_ptr<const CameraProjection> MrcalCamera(const MrcalCameraModel& model);

// Reads a pair of mrcal cameras: X_right = R X_left + T from their
// extrinsics (both relative to mrcal's reference frame).
void MrcalRelativePose(const MrcalCameraModel& left, const MrcalCameraModel& right,
                       Eigen::Matrix3d* R, Eigen::Vector3d* T);

}  // namespace ws
