#include "interop/ros_camera_info.h"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "interop/number_text.h"
#include "interop/opencv_lens.h"
#include "interop/yaml_fields.h"
#include "rig/rig_file.h"
#include "runtime/atomic_file.h"

namespace ws {
namespace {

std::string Matrix(int rows, int cols, const double* data) {
  return "\n  rows: " + std::to_string(rows) + "\n  cols: " + std::to_string(cols) + "\n  data: [" +
         NumberList(data, rows * cols) + "]";
}

// A {rows, cols, data} map of rows x cols numbers, cols from min_cols to max_cols.
std::vector<double> MatrixField(const YamlFields& in, const YAML::Node& root, const std::string& key, int rows,
                                int min_cols, int max_cols) {
  const YAML::Node node = root[key];
  if (!node || !node.IsMap()) in.Fail(key, "missing or not a map of rows, cols and data");
  const int r = in.Whole(node["rows"], key + ".rows", rows, rows);
  const int c = in.Whole(node["cols"], key + ".cols", min_cols, max_cols);
  return in.Numbers(node["data"], key + ".data", r * c);
}

}  // namespace

RosCameraInfo ReadRosCameraInfo(const std::string& path) {
  const YamlFields in(path);
  const YAML::Node root = in.Load(size_t(1) << 20);  // a camera_info is under 2 kB
  if (!root.IsMap()) in.Fail("(file)", "not a map of camera_info fields");
  RosCameraInfo info;
  info.name = root["camera_name"] ? in.Text(root["camera_name"], "camera_name") : "";
  info.width = in.Whole(root["image_width"], "image_width", 1, 1'000'000);
  info.height = in.Whole(root["image_height"], "image_height", 1, 1'000'000);
  info.distortion_model = in.Text(root["distortion_model"], "distortion_model");
  const std::vector<double> K = MatrixField(in, root, "camera_matrix", 3, 3, 3);
  info.D = MatrixField(in, root, "distortion_coefficients", 1, 0, 14);  // OpenCV's most
  const std::vector<double> R = MatrixField(in, root, "rectification_matrix", 3, 3, 3);
  const std::vector<double> P = MatrixField(in, root, "projection_matrix", 3, 4, 4);
  std::copy(K.begin(), K.end(), info.K.val);
  std::copy(R.begin(), R.end(), info.R.val);
  std::copy(P.begin(), P.end(), info.P.val);
  return info;
}

CameraModel RosCameraModel(const RosCameraInfo& info, const std::string& path) {
  const YamlFields in(path);
  CameraModel m;
  m.image_width = info.width, m.image_height = info.height;
  m.fx = info.K(0, 0), m.fy = info.K(1, 1), m.cx = info.K(0, 2), m.cy = info.K(1, 2);
  if (info.K(0, 1) != 0 || info.K(1, 0) != 0 || info.K(2, 0) != 0 || info.K(2, 1) != 0 || info.K(2, 2) != 1)
    in.Fail("camera_matrix", "not [fx 0 cx; 0 fy cy; 0 0 1]");
  const std::vector<double>& D = info.D;
  const std::string& model = info.distortion_model;
  const bool opencv = (model == "plumb_bob" && D.size() == 5) || (model == "rational_polynomial" && D.size() == 14);
  if (model == "plumb_bob" && D.empty()) {
    m.distortion = Distortion{ModelKind::kPoly6, 0, {}, {0, 0, 0}};
  } else if (model == "equidistant" && D.size() == 4) {
    m.distortion = Distortion{ModelKind::kKb4, 0, {}, D};
  } else if (!opencv || !OpenCvPoly6(D, &m)) {
    in.Fail("distortion_model", "'" + model + "' with " + std::to_string(D.size()) +
                                    " coefficients: only plumb_bob (5 or none), rational_polynomial (14: "
                                    "OpenCV's tilted sensor over k1 k2 p1 p2 k3) and equidistant (4) are read");
  }
  try {
    const Camera check(m);
  } catch (const std::exception& e) {
    in.Fail("camera_matrix", e.what());
  }
  return m;
}

void WriteRosCameraInfo(const std::string& path, const RosCameraInfo& info,
                        const std::vector<std::string>& comments) {
  std::ostringstream out;
  for (const std::string& line : comments) out << "# " << line << "\n";
  out << "image_width: " << info.width << "\nimage_height: " << info.height
      << "\ncamera_name: " << info.name << "\ncamera_matrix:" << Matrix(3, 3, info.K.val)
      << "\ndistortion_model: " << info.distortion_model
      << "\ndistortion_coefficients:" << Matrix(1, int(info.D.size()), info.D.data())
      << "\nrectification_matrix:" << Matrix(3, 3, info.R.val)
      << "\nprojection_matrix:" << Matrix(3, 4, info.P.val) << "\n";
  WriteFileAtomically(path, out.str());
}

}  // namespace ws
