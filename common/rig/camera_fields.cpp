#include "rig/camera_fields.h"

#include <algorithm>
#include <iterator>
#include <type_traits>

#include "models/bspline_basis.h"
#include "models/camera_field_table.h"
#include "models/model_registry.h"
#include "models/nonradial_field.h"

namespace ws {
namespace {

// A coefficient vector as a 1 x N !!opencv-matrix: `fs["left"]["k"] >> D`
// gives OpenCV its cv::Mat D (an empty one stays an empty list).
void WriteVector(cv::FileStorage& fs, const std::string& key, const std::vector<double>& values) {
  fs << key;
  if (values.empty()) {
    fs << values;
  } else {
    fs << cv::Mat(1, int(values.size()), CV_64F, const_cast<double*>(values.data()));
  }
}

// The fields `for_each` visits (camera_field_table.h) into the map open in
// fs: fx, fy, cx, cy as OpenCV's camera_matrix, the model by its name, every
// vector a matrix (WriteVector), the non-radial part a map of its own.
template <class ForEach>
void WriteFields(cv::FileStorage& fs, ForEach&& for_each) {
  const std::string intrinsics[] = {"fx", "fy", "cx", "cy"};
  double K[4] = {};  // fx, fy, cx, cy, written as the matrix once cy comes
  for_each([&](const std::string& key, const auto& value) {
    using T = std::decay_t<decltype(value)>;
    if constexpr (std::is_same_v<T, NonRadial>) {
      fs << key << "{";
      WriteFields(fs, [&](auto&& visit) { ForEachNonRadialField(value, visit); });
      fs << "}";
    } else if constexpr (std::is_same_v<T, ModelKind>) {
      fs << key << ModelName(value);
    } else if constexpr (std::is_same_v<T, std::vector<double>>) {
      WriteVector(fs, key, value);
    } else if constexpr (std::is_class_v<T>) {  // a std::array
      fs << key << std::vector<double>(value.begin(), value.end());
    } else if (const auto* i = std::find(std::begin(intrinsics), std::end(intrinsics), key);
               i != std::end(intrinsics)) {
      K[i - intrinsics] = double(value);
      if (*i == "cy") fs << "camera_matrix" << cv::Mat(cv::Matx33d(K[0], 0, K[2], 0, K[1], K[3], 0, 0, 1));
    } else {
      fs << key << value;
    }
  });
}

// A camera's non-radial field: its grid (4 to 64 control points a side),
// rectangle and 2 cols rows coefficients, and/or its sensor tilt.
NonRadial ReadNonRadial(const YamlReader& in, const cv::FileNode& node, const std::string& at) {
  if (!node.isMap() || (node["cols"].empty() && node["tilt"].empty()))
    in.Fail(at.substr(0, at.size() - 1), "not a map of cols, rows, domain, coeffs and/or tilt");
  NonRadial f;
  if (!node["tilt"].empty()) {
    const std::vector<double> tilt = in.Reals(node, "tilt", at + "tilt", 2);
    if (tilt.size() != 2) in.Fail(at + "tilt", "not the 2 numbers tau_x tau_y");
    std::copy(tilt.begin(), tilt.end(), f.tilt.begin());
  }
  if (node["cols"].empty()) return f;
  f.cols = in.Int(node, "cols", at + "cols", 4);
  f.rows = in.Int(node, "rows", at + "rows", 4);
  if (f.cols > 64 || f.rows > 64) in.Fail(at + "cols", "at most 64 control points a side");
  const std::vector<double> domain = in.Reals(node, "domain", at + "domain", 4);
  if (domain.size() != 4) in.Fail(at + "domain", "not the 4 numbers s0 s1 t0 t1");
  std::copy(domain.begin(), domain.end(), f.domain.begin());
  f.coeffs = in.Reals(node, "coeffs", at + "coeffs", NonRadialField::kMaxCoeffs);
  if (f.coeffs.size() != size_t(2 * f.cols * f.rows))
    in.Fail(at + "coeffs", std::to_string(f.coeffs.size()) + " numbers, not 2 cols rows = " +
                               std::to_string(2 * f.cols * f.rows));
  try {
    NonRadialField::FromData(f);
  } catch (const std::exception& e) {
    in.Fail(at + "domain", e.what());
  }
  return f;
}

}  // namespace

void WriteCameraFields(cv::FileStorage& fs, const CameraModel& m) {
  WriteFields(fs, [&](auto&& visit) { ForEachCameraField(m, visit); });
}

CameraModel ReadCameraFields(const YamlReader& in, const cv::FileNode& node, const std::string& at) {
  CameraModel m;
  m.image_width = in.Int(node, "image_width", at + "image_width", 1);
  m.image_height = in.Int(node, "image_height", at + "image_height", 1);
  ReadCameraMatrix(in, node, "camera_matrix", at + "camera_matrix", &m);
  Distortion& d = m.distortion;
  d.kind = ReadModelKind(in, node, at + "model");
  const ModelTraits& traits = Traits(d.kind);
  const std::string coeffs_key = traits.coeff_key;
  for (const ModelTraits& other : kModelTraits)
    if (other.coeff_key != coeffs_key && !node[other.coeff_key].empty())
      in.Fail(at + other.coeff_key, "not a coefficient of a " + ModelName(d.kind) + " model");
  if (traits.spline) {
    d.degree = in.Int(node, "degree", at + "degree", 1);
    d.knots = in.Reals(node, "knots", at + "knots", kMaxKnots);
  } else {
    if (!node["degree"].empty() && in.Int(node, "degree", at + "degree", 0) != 0)
      in.Fail(at + "degree", "must be 0 for " + ModelName(d.kind));
    if (!node["knots"].empty() && !in.Reals(node, "knots", at + "knots", kMaxKnots).empty())
      in.Fail(at + "knots", "must be empty for " + ModelName(d.kind));
  }
  d.coeffs = in.Reals(node, coeffs_key, at + coeffs_key, kMaxKnots);
  try {
    MakeModel(d, Coefficients::kAll);
  } catch (const std::exception& e) {
    in.Fail(at + (traits.spline ? "knots" : "model"), e.what());
  }
  m.p1 = in.Real(node, "p1", at + "p1");
  m.p2 = in.Real(node, "p2", at + "p2");
  if (!node["nonradial"].empty()) m.nonradial = ReadNonRadial(in, node["nonradial"], at + "nonradial.");
  try {
    const Camera check(m);
  } catch (const std::exception& e) {
    in.Fail(at + coeffs_key, e.what());
  }
  return m;
}

void ReadCameraMatrix(const YamlReader& in, const cv::FileNode& node, const std::string& key, const std::string& field,
                      CameraModel* m) {
  const Eigen::MatrixXd K = in.Matrix(node, key, field, 3, 3);
  if (K(0, 1) != 0 || K(1, 0) != 0 || K(2, 0) != 0 || K(2, 1) != 0 || K(2, 2) != 1)
    in.Fail(field, "not of the form [fx 0 cx; 0 fy cy; 0 0 1]");
  if (!(K(0, 0) > 0) || !(K(1, 1) > 0)) in.Fail(field, "fx and fy must be positive");
  m->fx = K(0, 0);
  m->fy = K(1, 1);
  m->cx = K(0, 2);
  m->cy = K(1, 2);
}

ModelKind ReadModelKind(const YamlReader& in, const cv::FileNode& node, const std::string& field) {
  const std::string name = in.String(node, "model", field);
  try {
    return ParseModelKind(name);
  } catch (const std::invalid_argument&) {
    in.Fail(field, "unknown model '" + name + "' (known: " + KnownModelNames() + ")");
  }
}

}  // namespace ws
