#include "interop/exact_model.h"

#include <array>
#include <stdexcept>

namespace ws {
namespace {

constexpr ExportFormat kFormats[] = {ExportFormat::kOpenCv, ExportFormat::kRos,
                                     ExportFormat::kKalibr, ExportFormat::kMrcal};

// k1, k2, k3 of a poly6 (or of a poly12 whose k4..k6 are 0); nullopt otherwise.
std::optional<std::vector<double>> Brown(const CameraModel& camera) {
  const Distortion& d = camera.distortion;
  if (d.kind == ModelKind::kPoly6 && d.coeffs.size() == 3) return d.coeffs;
  if (d.kind == ModelKind::kPoly12 && d.coeffs.size() == 6 && d.coeffs[3] == 0 && d.coeffs[4] == 0 &&
      d.coeffs[5] == 0)
    return std::vector<double>(d.coeffs.begin(), d.coeffs.begin() + 3);
  return std::nullopt;
}

}  // namespace

const char* ExportFormatName(ExportFormat format) {
  switch (format) {
    case ExportFormat::kOpenCv: return "opencv-stereo";
    case ExportFormat::kRos: return "ros";
    case ExportFormat::kKalibr: return "kalibr";
    case ExportFormat::kMrcal: return "mrcal";
  }
  return "";
}

ExportFormat ParseExportFormat(const std::string& name) {
  for (ExportFormat format : kFormats)
    if (name == ExportFormatName(format)) return format;
  throw std::invalid_argument("unknown format '" + name + "' (opencv-stereo, ros, kalibr, mrcal)");
}

std::optional<TargetModel> ExactTargetModel(const CameraModel& camera, ExportFormat format) {
  if (camera.nonradial.cols > 0) return std::nullopt;  // no other format has a non-radial field
  const double p1 = camera.p1, p2 = camera.p2;
  if (camera.nonradial.tilted()) {
    // OpenCV's 14 coefficients k1 k2 p1 p2 k3 k4 k5 k6 s1 s2 s3 s4 tauX tauY
    // (CALIB_TILTED_MODEL), the same tilt after the same distortion.
    // ROS's rational_polynomial is OpenCV's model with D as long as given
    // (image_geometry hands it to cv::initUndistortRectifyMap as it stands).
    const auto k = Brown(camera);
    if (!k || format == ExportFormat::kKalibr || format == ExportFormat::kMrcal) return std::nullopt;
    const std::array<double, 2>& tau = camera.nonradial.tilt;
    return TargetModel{format == ExportFormat::kRos ? "rational_polynomial" : "pinhole",
                       {(*k)[0], (*k)[1], p1, p2, (*k)[2], 0, 0, 0, 0, 0, 0, 0, tau[0], tau[1]}};
  }
  if (const auto k = Brown(camera)) {
    const std::vector<double> opencv{(*k)[0], (*k)[1], p1, p2, (*k)[2]};
    switch (format) {
      case ExportFormat::kOpenCv: return TargetModel{"pinhole", opencv};
      case ExportFormat::kRos: return TargetModel{"plumb_bob", opencv};
      case ExportFormat::kMrcal: return TargetModel{"LENSMODEL_OPENCV5", opencv};
      case ExportFormat::kKalibr:
        if ((*k)[2] != 0) return std::nullopt;  // radtan is k1, k2, p1, p2 only
        return TargetModel{"radtan", {(*k)[0], (*k)[1], p1, p2}};
    }
  }
  if (camera.distortion.kind == ModelKind::kKb4 && camera.distortion.coeffs.size() == 4) {
    switch (format) {
      case ExportFormat::kOpenCv: return TargetModel{"fisheye", camera.distortion.coeffs};
      case ExportFormat::kRos:
      case ExportFormat::kKalibr: return TargetModel{"equidistant", camera.distortion.coeffs};
      case ExportFormat::kMrcal: return std::nullopt;
    }
  }
  return std::nullopt;
}

}  // namespace ws
