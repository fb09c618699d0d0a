#include "interop/mrcal_cameramodel.h"

#include <cmath>
#include <sstream>

#include <Eigen/Geometry>

#include "interop/foreign_camera.h"
#include "interop/mrcal_spline.h"
#include "interop/number_text.h"
#include "interop/opencv_lens.h"
#include "interop/python_literal.h"
#include "rig/rig_file.h"
#include "runtime/atomic_file.h"
#include "runtime/bounded_file.h"

namespace ws {
namespace {

std::vector<double> Numbers(const std::string& path, const PyLiteral& dict, const std::string& key) {
  const auto found = dict.entries.find(key);
  if (found == dict.entries.end()) throw CalibrationFileError(path + ": " + key + ": missing");
  if (found->second.kind != PyLiteral::Kind::kList)
    throw CalibrationFileError(path + ": " + key + ": not a list of numbers");
  std::vector<double> out;
  for (const PyLiteral& item : found->second.items) {
    if (item.kind != PyLiteral::Kind::kNumber || !std::isfinite(item.number))
      throw CalibrationFileError(path + ": " + key + ": not a list of finite numbers");
    out.push_back(item.number);
  }
  return out;
}

Eigen::Matrix3d RotationOf(const double* r) {
  const Eigen::Vector3d w(r[0], r[1], r[2]);
  if (w.norm() == 0) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(w.norm(), w.normalized()).toRotationMatrix();
}

}  // namespace

MrcalCameraModel ReadMrcalCameraModel(const std::string& path) {
  std::string text;
  try {
    text = ReadBoundedFile(path, kMaxCameraModelBytes);
  } catch (const BoundedFileError& e) {
    throw CalibrationFileError(path + ": (file): " + e.what());
  }
  PyLiteral dict;
  try {
    dict = ParsePyLiteral(text);
  } catch (const std::invalid_argument& e) {
    throw CalibrationFileError(path + ": (file): not a mrcal .cameramodel (a Python dict): " +
                               e.what());
  }
  if (dict.kind != PyLiteral::Kind::kDict)
    throw CalibrationFileError(path + ": (file): not a mrcal .cameramodel (a Python dict)");
  MrcalCameraModel m;
  const auto lensmodel = dict.entries.find("lensmodel");
  if (lensmodel == dict.entries.end() || lensmodel->second.kind != PyLiteral::Kind::kString)
    throw CalibrationFileError(path + ": lensmodel: missing or not a string");
  m.lensmodel = lensmodel->second.text;
  m.intrinsics = Numbers(path, dict, "intrinsics");
  const std::vector<double> extrinsics = Numbers(path, dict, "extrinsics");
  if (extrinsics.size() != 6) throw CalibrationFileError(path + ": extrinsics: not 6 numbers");
  std::copy(extrinsics.begin(), extrinsics.end(), m.extrinsics.begin());
  const std::vector<double> size = Numbers(path, dict, "imagersize");
  if (size.size() != 2 || !(size[0] >= 1 && size[1] >= 1 && size[0] < 1e6 && size[1] < 1e6) ||
      size[0] != std::floor(size[0]) || size[1] != std::floor(size[1]))
    throw CalibrationFileError(path + ": imagersize: not two positive integers");
  m.width = int(size[0]);
  m.height = int(size[1]);
  try {
    MrcalCamera(m);
  } catch (const std::invalid_argument& e) {
    throw CalibrationFileError(path + ": intrinsics: " + e.what());
  }
  return m;
}

void WriteMrcalCameraModel(const std::string& path, const MrcalCameraModel& m,
                           const std::vector<std::string>& comments) {
  std::ostringstream out;
  auto list = [&](const auto& values) { out << "[ " << NumberList(values.data(), int(values.size())) << " ]"; };
  for (const std::string& line : comments) out << "# " << line << "\n";
  out << "{\n    'lensmodel': '" << m.lensmodel << "',\n    # fx, fy, cx, cy, distortion...\n"
      << "    'intrinsics': ";
  list(m.intrinsics);
  out << ",\n    # rt_fromref\n    'extrinsics': ";
  list(m.extrinsics);
  out << ",\n    'imagersize': [ " << m.width << ", " << m.height << " ],\n}\n";
  WriteFileAtomically(path, out.str());
}

std::shared_ptr<const CameraProjection> MrcalCamera(const MrcalCameraModel& m) {
  const std::vector<double>& in = m.intrinsics;
  auto expect = [&](size_t count) {
    if (in.size() != count)
      throw std::invalid_argument(m.lensmodel + " has " + std::to_string(count) +
                                  " intrinsics, the file " + std::to_string(in.size()));
  };
  const std::string name = "mrcal " + m.lensmodel;
  if (m.lensmodel == "LENSMODEL_PINHOLE" || m.lensmodel == "LENSMODEL_OPENCV4" ||
      m.lensmodel == "LENSMODEL_OPENCV5") {
    const size_t count = m.lensmodel == "LENSMODEL_PINHOLE" ? 4 : m.lensmodel == "LENSMODEL_OPENCV4" ? 8 : 9;
    expect(count);
    CameraModel camera;
    camera.image_width = m.width;
    camera.image_height = m.height;
    camera.fx = in[0], camera.fy = in[1], camera.cx = in[2], camera.cy = in[3];
    std::vector<double> k(3, 0.0);
    if (count > 4) {
      k[0] = in[4], k[1] = in[5], camera.p1 = in[6], camera.p2 = in[7];
      if (count == 9) k[2] = in[8];
    }
    camera.distortion = Distortion{ModelKind::kPoly6, 0, {}, k};
    return std::make_shared<WidestereoProjection>(camera);
  }
  if (m.lensmodel == "LENSMODEL_OPENCV8" || m.lensmodel == "LENSMODEL_OPENCV12") {
    const bool prism = m.lensmodel == "LENSMODEL_OPENCV12";
    expect(prism ? 16 : 12);
    // mrcal's order: k1 k2 p1 p2 k3 k4 k5 k6 [s1 s2 s3 s4]
    std::vector<double> k{in[4], in[5], in[8], in[9], in[10], in[11], 0, 0, 0, 0};
    if (prism) std::copy(in.begin() + 12, in.end(), k.begin() + 6);
    return std::make_shared<ForeignCamera<OpenCvLens>>(
        name, m.width, m.height, OpenCvLens(),
        std::array<double, kNumIntrinsics>{in[0], in[1], in[2], in[3], in[6], in[7]}, k);
  }
  if (m.lensmodel.rfind("LENSMODEL_SPLINED_STEREOGRAPHIC", 0) == 0) {
    const MrcalSpline spline(MrcalSplineConfig::Parse(m.lensmodel));
    expect(4 + spline.NumCoeffs());
    return std::make_shared<ForeignCamera<MrcalSpline>>(
        name, m.width, m.height, spline,
        std::array<double, kNumIntrinsics>{in[0], in[1], in[2], in[3], 0, 0},
        std::vector<double>(in.begin() + 4, in.end()));
  }
  throw std::invalid_argument("lens model '" + m.lensmodel +
                              "' is not one widestereo reads (LENSMODEL_PINHOLE, OPENCV4, OPENCV5, "
                              "OPENCV8, OPENCV12, SPLINED_STEREOGRAPHIC_order=3_...)");
}

void MrcalRelativePose(const MrcalCameraModel& left, const MrcalCameraModel& right,
                       Eigen::Matrix3d* R, Eigen::Vector3d* T) {
  // X_i = R_i X_ref + t_i, so X_right = R_r R_l^T (X_left - t_l) + t_r.
  const Eigen::Matrix3d Rl = RotationOf(left.extrinsics.data());
  const Eigen::Matrix3d Rr = RotationOf(right.extrinsics.data());
  const Eigen::Vector3d tl(left.extrinsics[3], left.extrinsics[4], left.extrinsics[5]);
  const Eigen::Vector3d tr(right.extrinsics[3], right.extrinsics[4], right.extrinsics[5]);
  *R = Rr * Rl.transpose();
  *T = tr - *R * tl;
}

}  // namespace ws
