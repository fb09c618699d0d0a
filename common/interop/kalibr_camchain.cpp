#include "interop/kalibr_camchain.h"

#include <cmath>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "interop/number_text.h"
#include "interop/yaml_fields.h"
#include "rig/rig_file.h"
#include "runtime/atomic_file.h"

namespace ws {
namespace {

CameraModel ReadCamera(const YamlFields& in, const YAML::Node& cam, const std::string& name) {
  if (!cam.IsMap()) in.Fail(name, "not a map of camera fields");
  const std::string model = in.Text(cam["camera_model"], name + ".camera_model");
  if (model != "pinhole")
    in.Fail(name + ".camera_model", "'" + model + "': only pinhole is read (with radtan or equidistant)");
  const std::vector<double> k = in.Numbers(cam["intrinsics"], name + ".intrinsics", 4);
  const std::vector<double> size = in.Numbers(cam["resolution"], name + ".resolution", 2);
  CameraModel m;
  if (!(size[0] >= 1 && size[1] >= 1 && size[0] < 1e6 && size[1] < 1e6))
    in.Fail(name + ".resolution", "not a positive size");
  m.image_width = int(size[0]);
  m.image_height = int(size[1]);
  m.fx = k[0], m.fy = k[1], m.cx = k[2], m.cy = k[3];
  const std::string distortion = in.Text(cam["distortion_model"], name + ".distortion_model");
  const std::string coeffs = name + ".distortion_coeffs";
  if (distortion == "radtan") {
    const std::vector<double> d = in.Numbers(cam["distortion_coeffs"], coeffs, 4);
    m.distortion = Distortion{ModelKind::kPoly6, 0, {}, {d[0], d[1], 0}};
    m.p1 = d[2], m.p2 = d[3];
  } else if (distortion == "equidistant") {
    m.distortion = Distortion{ModelKind::kKb4, 0, {}, in.Numbers(cam["distortion_coeffs"], coeffs, 4)};
  } else if (distortion == "none") {
    m.distortion = Distortion{ModelKind::kPoly6, 0, {}, {0, 0, 0}};
  } else {
    in.Fail(name + ".distortion_model", "'" + distortion + "': only radtan, equidistant and none are read");
  }
  try {
    const Camera check(m);
  } catch (const std::exception& e) {
    in.Fail(name, e.what());
  }
  return m;
}

std::string List(const double* values, int count) { return "[" + NumberList(values, count) + "]"; }

}  // namespace

AnyRig ReadKalibrCamchain(const std::string& path) {
  const YamlFields in(path);
  const YAML::Node root = in.Load(size_t(1) << 20);  // a camchain is a few kB
  if (!root.IsMap() || !root["cam0"]) in.Fail("cam0", "missing (not a Kalibr camchain)");
  AnyRig rig;
  rig.format = "kalibr";
  rig.left = std::make_shared<WidestereoProjection>(ReadCamera(in, root["cam0"], "cam0"));
  rig.mono = !root["cam1"];
  if (rig.mono) return rig;
  rig.right = std::make_shared<WidestereoProjection>(ReadCamera(in, root["cam1"], "cam1"));
  const YAML::Node t = root["cam1"]["T_cn_cnm1"];
  if (!t || !t.IsSequence() || t.size() != 4) in.Fail("cam1.T_cn_cnm1", "missing or not 4x4");
  Eigen::Matrix4d M;
  for (int r = 0; r < 4; ++r) {
    const std::vector<double> row = in.Numbers(t[r], "cam1.T_cn_cnm1", 4);
    for (int c = 0; c < 4; ++c) M(r, c) = row[c];
  }
  rig.R = M.topLeftCorner<3, 3>();
  rig.T = M.topRightCorner<3, 1>();
  if (!IsRotation(rig.R) || M.row(3) != Eigen::RowVector4d(0, 0, 0, 1))
    in.Fail("cam1.T_cn_cnm1", "not a rigid transform [R T; 0 0 0 1]");
  return rig;
}

void WriteKalibrCamchain(const std::string& path, const std::vector<KalibrCamera>& cameras,
                         const Eigen::Matrix3d& R, const Eigen::Vector3d& T,
                         const std::vector<std::string>& comments) {
  std::ostringstream out;
  for (const std::string& line : comments) out << "# " << line << "\n";
  for (size_t i = 0; i < cameras.size(); ++i) {
    const CameraModel& m = *cameras[i].camera;
    const TargetModel& d = cameras[i].distortion;
    const double intrinsics[4] = {m.fx, m.fy, m.cx, m.cy};
    const double resolution[2] = {double(m.image_width), double(m.image_height)};
    out << "cam" << i << ":\n";
    if (i == 1) {
      out << "  T_cn_cnm1:\n";
      for (int r = 0; r < 4; ++r) {
        const double row[4] = {r < 3 ? R(r, 0) : 0, r < 3 ? R(r, 1) : 0, r < 3 ? R(r, 2) : 0,
                               r < 3 ? T(r) : 1};
        out << "  - " << List(row, 4) << "\n";
      }
      out << "  cam_overlaps: [0]\n";
    } else if (cameras.size() > 1) {
      out << "  cam_overlaps: [1]\n";
    }
    out << "  camera_model: pinhole\n  intrinsics: " << List(intrinsics, 4)
        << "\n  distortion_model: " << d.name
        << "\n  distortion_coeffs: " << List(d.coeffs.data(), int(d.coeffs.size()))
        << "\n  resolution: " << List(resolution, 2) << "\n  rostopic: /cam" << i << "/image_raw\n";
  }
  WriteFileAtomically(path, out.str());
}

}  // namespace ws
