#include "rig/rig_file.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <opencv2/core.hpp>

#include "models/camera_ranges.h"
#include "models/model_registry.h"
#include "rig/camera_fields.h"
#include "runtime/atomic_file.h"

namespace ws {
namespace {

const std::string kHeader[] = {
    std::string(kCalibrationFileTitle) + " (docs/models.md). Pixel of a camera-frame point (X,Y,Z):",
    "  bspline, poly6, poly12: x = X/Z, y = Y/Z (Z > 0);",
    "  kb4, bspline_theta: x = theta X/rho, y = theta Y/rho, rho = sqrt(X^2 + Y^2),",
    "    theta = atan2(rho, Z) (the incidence angle, radians; rays beyond 90 degrees too);",
    "  r = sqrt(x^2 + y^2)",
    "  xd = (1 + D(r)) x + 2 p1 x y + p2 (r^2 + 2 x^2)",
    "  yd = (1 + D(r)) y + p1 (r^2 + 2 y^2) + 2 p2 x y",
    "  (xt, yt) = (x' / w', y' / w'), [x'; y'; w'] = M(tau) [xd; yd; 1], (xd, yd) without 'tilt'",
    "  (xf, yf) = (xt, yt) + F(xt, yt), F = 0 without 'nonradial' 'cols'",
    "  u = fx xf + cx,  v = fy yf + cy   (pixel centres at integer coordinates, as in OpenCV)",
    "D(r): bspline: sum_i alpha_i N_{i,degree}(r), the de Boor-Cox B-spline basis on 'knots'",
    "      (clamped; beyond the last knot the last polynomial piece continues);",
    "      poly6: k1 r^2 + k2 r^4 + k3 r^6; poly12: k1 r^2 + ... + k6 r^12;",
    "      bspline_theta: as bspline, over theta; kb4: k1 r^2 + ... + k4 r^8 with p1 = p2 = 0,",
    "      cv::fisheye's model: camera_matrix is its K and k its D.",
    "F(s, t): nonradial: sum_ij c_ij N_i(s) M_j(t), clamped uniform cubic B-splines of 'cols' x",
    "      'rows' control points over 'domain' [s0 s1 t0 t1] (outside it: its nearest point);",
    "      'coeffs' the x components c_ij at j cols + i, then the y components (docs/models.md).",
    "M(tau): nonradial: 'tilt' [tau_x tau_y] (radians), OpenCV's tilted sensor (CALIB_TILTED_MODEL):",
    "      M = [cx 0 0; -sx sy cy 0; sy -cy sx cy cx], cx = cos tau_x, sx = sin tau_x, cy, sy of tau_y.",
    "Stereo: X_right = R X_left + T (metres)."};

void WriteCamera(cv::FileStorage& fs, const std::string& name, const CameraModel& m, double rms,
                 int views) {
  fs << name << "{";
  WriteCameraFields(fs, m);
  fs << "rms" << rms << "views" << views;
  fs << "}";
}

CameraModel ReadCamera(const YamlReader& in, const cv::FileNode& root, const std::string& name,
                       double* rms, int* views) {
  const cv::FileNode node = in.Map(root, name, name);
  const CameraModel m = ReadCameraFields(in, node, name + ".");
  *rms = in.Real(node, "rms", name + ".rms");
  if (*rms < 0) in.Fail(name + ".rms", "negative");
  *views = in.Int(node, "views", name + ".views", 0);
  return m;
}

}  // namespace

void WriteCalibrationFile(const std::string& path, const Rig& rig) {
  std::string text;
  {
    cv::FileStorage fs(".yaml", cv::FileStorage::WRITE | cv::FileStorage::MEMORY | cv::FileStorage::FORMAT_YAML);
    for (const std::string& line : kHeader) fs.writeComment(line);
    if (!rig.note.empty()) fs.writeComment(rig.note);
    fs << "model" << ModelName(rig.kind());
    WriteCamera(fs, "left", rig.left, rig.left_rms, rig.left_views);
    if (!rig.mono) {
      WriteCamera(fs, "right", rig.right, rig.right_rms, rig.right_views);
      cv::Mat R(3, 3, CV_64F), T(3, 1, CV_64F);
      for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) R.at<double>(r, c) = rig.R(r, c);
        T.at<double>(r) = rig.T(r);
      }
      fs << "stereo"
         << "{"
         << "R" << R << "T" << T << "rms" << rig.rms << "baseline_m" << rig.T.norm() << "views"
         << rig.views << "}";
    }
    text = fs.releaseAndGetString();
  }
  WriteFileAtomically(path, text);
}

Rig ReadCalibrationFile(const std::string& path) {
  const YamlReader in(path, "with stereo-calibrate --out");
  cv::FileStorage fs;
  // Refuses the layouts OpenCV's reader hangs or crashes on, and files far
  // larger than a calibration (two cameras of kMaxKnots knots and
  // coefficients and a field of NonRadialField::kMaxCoeffs: 500 KB).
  constexpr size_t kMaxCalibrationFileBytes = size_t(4) << 20;
  const cv::FileNode root = in.Open(fs, kMaxCalibrationFileBytes);
  Rig f;
  const ModelKind model = ReadModelKind(in, root, "model");
  f.left = ReadCamera(in, root, "left", &f.left_rms, &f.left_views);
  // The ranges every way in shares (a STEREO_CALIBRATION message's too:
  // models/camera_ranges.h): fx = 1e-300 would load, and match with f = 0 px.
  auto in_range = [&](const CameraModel& camera, const char* name) {
    try {
      CheckCameraRanges(camera);
    } catch (const std::invalid_argument& e) {
      in.Fail(name, e.what());
    }
  };
  in_range(f.left, "left");
  // A one-camera file has neither "right" nor "stereo".
  f.mono = root["right"].empty() && root["stereo"].empty();
  if (f.mono) {
    if (f.left.distortion.kind != model)
      in.Fail("model", "'" + ModelName(model) + "', but the camera's model is '" +
                           ModelName(f.left.distortion.kind) + "'");
    return f;
  }
  f.right = ReadCamera(in, root, "right", &f.right_rms, &f.right_views);
  in_range(f.right, "right");
  for (const auto* camera : {&f.left, &f.right})
    if (camera->distortion.kind != model)
      in.Fail("model",
              "'" + ModelName(model) + "', but a camera's model is '" + ModelName(camera->distortion.kind) + "'");
  const cv::FileNode stereo = in.Map(root, "stereo", "stereo");
  f.R = in.Matrix(stereo, "R", "stereo.R", 3, 3);
  if (!(f.R.transpose() * f.R).isApprox(Eigen::Matrix3d::Identity(), 1e-6) ||
      !(f.R.determinant() > 0))
    in.Fail("stereo.R", "not a rotation (R^T R = I, det R = +1)");
  f.T = in.Matrix(stereo, "T", "stereo.T", 3, 1);
  if (!(f.T.norm() > 0)) in.Fail("stereo.T", "a zero baseline (T = 0): the two cameras are at one place");
  f.rms = in.Real(stereo, "rms", "stereo.rms");
  if (f.rms < 0) in.Fail("stereo.rms", "negative");
  const double baseline = in.Real(stereo, "baseline_m", "stereo.baseline_m");
  if (!(std::abs(baseline - f.T.norm()) <= 1e-9 * std::max(1.0, f.T.norm())))
    in.Fail("stereo.baseline_m", "differs from |T| = " + std::to_string(f.T.norm()));
  f.views = in.Int(stereo, "views", "stereo.views", 0);
  return f;
}

Rig StereoRigFromFile(const std::string& path) {
  Rig rig = ReadCalibrationFile(path);
  if (rig.mono)
    throw CalibrationFileError(path + ": a one-camera calibration (no right camera, no "
                               "stereo): a stereo rig is needed");
  return rig;
}

}  // namespace ws
