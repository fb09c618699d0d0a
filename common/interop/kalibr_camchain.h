// Kalibr's camera chain, camchain.yaml (kalibr_calibrate_cameras; Kalibr's
// wiki, "Yaml formats"):
//
//   cam0:
//     camera_model: pinhole
//     intrinsics: [fu, fv, pu, pv]
//     distortion_model: radtan            radtan: [k1, k2, r1, r2]
//     distortion_coeffs: [...]            equidistant: [k1, k2, k3, k4]
//     resolution: [width, height]
//     rostopic: /cam0/image_raw
//   cam1:
//     T_cn_cnm1: 4x4                      X_cam1 = T X_cam0 (metres)
//     cam_overlaps: [0]
//     ... as cam0
//
// Both ways as widestereo's models: radtan is poly6 with k3 = 0 and
// equidistant is kb4, exactly (exact_model.h).
#pragma once

#include <string>
#include <vector>

#include "interop/any_rig.h"
#include "interop/exact_model.h"

namespace ws {

// cam0 (and cam1 when present). Throws CalibrationFileError
// "FILE: FIELD: REASON", e.g. for a camera model other than pinhole or a
// distortion model other than radtan, equidistant and none.
AnyRig ReadKalibrCamchain(const std::string& path);

struct KalibrCamera {
  const CameraModel* camera;  // its intrinsics and resolution
  TargetModel distortion;     // "radtan" or "equidistant", Kalibr's coefficients
};

// Writes cam0 and, for a pair, cam1 with T_cn_cnm1 = [R T; 0 1], each line
// of `comments` first as a # line. Throws std::runtime_error when it cannot.
void WriteKalibrCamchain(const std::string& path, const std::vector<KalibrCamera>& cameras,
                         const Eigen::Matrix3d& R, const Eigen::Vector3d& T,
                         const std::vector<std::string>& comments);

}  // namespace ws
