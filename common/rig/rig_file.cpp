#include "rig/rig_file.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <opencv2/core.hpp>

#include "models/bspline_basis.h"
#include "models/camera_ranges.h"
#include "models/model_registry.h"
#include "models/nonradial_field.h"
#include "runtime/atomic_file.h"
#include "runtime/opencv_yaml.h"

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

void WriteCamera(cv::FileStorage& fs, const std::string& name, const CameraModel& m, double rms,
                 int views) {
  fs << name << "{";
  fs << "image_width" << m.image_width << "image_height" << m.image_height;
  fs << "camera_matrix" << cv::Mat(cv::Matx33d(m.fx, 0, m.cx, 0, m.fy, m.cy, 0, 0, 1));
  const ModelTraits& traits = Traits(m.distortion.kind);
  fs << "model" << traits.name << "degree" << m.distortion.degree;
  if (traits.spline) WriteVector(fs, "knots", m.distortion.knots);
  WriteVector(fs, traits.coeff_key, m.distortion.coeffs);
  fs << "p1" << m.p1 << "p2" << m.p2 << "rms" << rms << "views" << views;
  if (!m.nonradial.empty()) {
    const NonRadial& f = m.nonradial;
    fs << "nonradial" << "{";
    if (f.cols > 0) {
      fs << "cols" << f.cols << "rows" << f.rows << "domain" << std::vector<double>(f.domain.begin(), f.domain.end());
      WriteVector(fs, "coeffs", f.coeffs);
    }
    if (f.tilted()) fs << "tilt" << std::vector<double>(f.tilt.begin(), f.tilt.end());
    fs << "}";
  }
  fs << "}";
}

// Typed, checked access to the fields of one file; every error names the
// file and the field.
class Reader {
 public:
  explicit Reader(std::string path) : path_(std::move(path)), cut_short_(EndsMidLine(path_)) {}

  [[noreturn]] void Fail(const std::string& field, const std::string& reason) const {
    throw CalibrationFileError(path_ + ": " + field + ": " + reason +
                               (cut_short_ ? " (the file ends mid-line: it was cut short; write it again, "
                                             "e.g. with stereo-calibrate --out)"
                                           : ""));
  }
  cv::FileNode Required(const cv::FileNode& parent, const std::string& key,
                        const std::string& field) const {
    const cv::FileNode node = parent[key];
    if (node.empty()) Fail(field, "missing");
    return node;
  }
  int Int(const cv::FileNode& parent, const std::string& key, const std::string& field,
          int min) const {
    const cv::FileNode node = Required(parent, key, field);
    if (!node.isInt()) Fail(field, "not an integer");
    const int value = static_cast<int>(node);
    if (value < min) Fail(field, std::to_string(value) + " is below " + std::to_string(min));
    return value;
  }
  double Real(const cv::FileNode& parent, const std::string& key, const std::string& field) const {
    const cv::FileNode node = Required(parent, key, field);
    return Number(node, field);
  }
  std::string String(const cv::FileNode& parent, const std::string& key,
                     const std::string& field) const {
    const cv::FileNode node = Required(parent, key, field);
    if (!node.isString()) Fail(field, "not a string");
    return static_cast<std::string>(node);
  }
  // At most `max_count` numbers: a 1 x N or N x 1 !!opencv-matrix of
  // doubles or floats (as written since the coefficient vectors load into
  // a cv::Mat), or a list (as written before). Its size is checked before
  // any is read, and the numbers are read in one pass (FileNode's
  // operator[] walks the list from its start: a long list read by index
  // took quadratic time).
  std::vector<double> Reals(const cv::FileNode& parent, const std::string& key, const std::string& field,
                            size_t max_count) const {
    cv::FileNode node = Required(parent, key, field);
    if (node.isMap()) {
      const std::string vector = "not a 1 x N !!opencv-matrix of numbers";
      const cv::FileNode rows = node["rows"], cols = node["cols"], dt = node["dt"];
      if (!rows.isInt() || !cols.isInt() || !dt.isString() || (int(rows) != 1 && int(cols) != 1) ||
          int(rows) < 0 || int(cols) < 0 || (std::string(dt) != "d" && std::string(dt) != "f"))
        Fail(field, vector);
      const size_t count = size_t(int(rows)) * size_t(int(cols));
      if (count > max_count) Fail(field, "more than " + std::to_string(max_count) + " numbers");
      node = node["data"];
      if (!node.isSeq() || node.size() != count) Fail(field, vector);
    }
    if (!node.isSeq()) Fail(field, "not a list of numbers");
    if (node.size() > max_count) Fail(field, "more than " + std::to_string(max_count) + " numbers");
    std::vector<double> values;
    values.reserve(node.size());
    for (const cv::FileNode& value : node)
      values.push_back(Number(value, field + "[" + std::to_string(values.size()) + "]"));
    return values;
  }
  Eigen::MatrixXd Matrix(const cv::FileNode& parent, const std::string& key,
                         const std::string& field, int rows, int cols) const {
    const cv::FileNode node = Required(parent, key, field);
    const std::string shape =
        "not a " + std::to_string(rows) + "x" + std::to_string(cols) + " !!opencv-matrix";
    // The size the file claims is checked first: OpenCV allocates it.
    if (!node.isMap() || !node["rows"].isInt() || !node["cols"].isInt() || int(node["rows"]) != rows ||
        int(node["cols"]) != cols)
      Fail(field, shape);
    cv::Mat mat;
    try {
      node >> mat;
    } catch (const cv::Exception&) {
      Fail(field, shape);
    }
    if (mat.rows != rows || mat.cols != cols || mat.channels() != 1) Fail(field, shape);
    mat.convertTo(mat, CV_64F);
    Eigen::MatrixXd out(rows, cols);
    for (int r = 0; r < rows; ++r)
      for (int c = 0; c < cols; ++c) out(r, c) = mat.at<double>(r, c);
    if (!out.allFinite()) Fail(field, "not finite");
    return out;
  }

 private:
  double Number(const cv::FileNode& node, const std::string& field) const {
    if (!node.isReal() && !node.isInt()) Fail(field, "not a number");
    const double value = static_cast<double>(node);
    if (!std::isfinite(value)) Fail(field, "not finite");
    return value;
  }

  // A file OpenCV wrote ends with a newline; one that does not was cut short.
  static bool EndsMidLine(const std::string& path) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) return false;  // never opens a FIFO (it would block)
    std::ifstream file(path, std::ios::binary | std::ios::ate);
    if (!file || file.tellg() <= 0) return false;
    file.seekg(-1, std::ios::end);
    return file.get() != '\n';
  }

  std::string path_;
  bool cut_short_;
};

// A camera's non-radial field: its grid (4 to 64 control points a side),
// rectangle and 2 cols rows coefficients.
NonRadial ReadNonRadial(const Reader& in, const cv::FileNode& node, const std::string& at) {
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

// The model kind named by node's "model" (`field` in messages).
ModelKind ReadModelKind(const Reader& in, const cv::FileNode& node, const std::string& field) {
  const std::string name = in.String(node, "model", field);
  try {
    return ParseModelKind(name);
  } catch (const std::invalid_argument&) {
    in.Fail(field, "unknown model '" + name + "' (known: " + KnownModelNames() + ")");
  }
}

CameraModel ReadCamera(const Reader& in, const cv::FileNode& root, const std::string& name,
                       double* rms, int* views) {
  const cv::FileNode node = in.Required(root, name, name);
  if (!node.isMap()) in.Fail(name, "not a map of camera fields");
  const std::string at = name + ".";
  CameraModel m;
  m.image_width = in.Int(node, "image_width", at + "image_width", 1);
  m.image_height = in.Int(node, "image_height", at + "image_height", 1);
  const Eigen::MatrixXd K = in.Matrix(node, "camera_matrix", at + "camera_matrix", 3, 3);
  if (K(0, 1) != 0 || K(1, 0) != 0 || K(2, 0) != 0 || K(2, 1) != 0 || K(2, 2) != 1)
    in.Fail(at + "camera_matrix", "not of the form [fx 0 cx; 0 fy cy; 0 0 1]");
  if (!(K(0, 0) > 0) || !(K(1, 1) > 0)) in.Fail(at + "camera_matrix", "fx and fy must be positive");
  m.fx = K(0, 0);
  m.fy = K(1, 1);
  m.cx = K(0, 2);
  m.cy = K(1, 2);
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
  *rms = in.Real(node, "rms", at + "rms");
  if (*rms < 0) in.Fail(at + "rms", "negative");
  *views = in.Int(node, "views", at + "views", 0);
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
  const Reader in(path);
  cv::FileStorage fs;
  try {
    // Refuses the layouts OpenCV's reader hangs or crashes on, and files far
    // larger than a calibration (two cameras of kMaxKnots knots and
    // coefficients and a field of NonRadialField::kMaxCoeffs: 500 KB).
    constexpr size_t kMaxCalibrationFileBytes = size_t(4) << 20;
    OpenOpenCvYaml(fs, path, kMaxCalibrationFileBytes);
  } catch (const YamlFileError& e) {
    in.Fail("(file)", e.what());
  }
  const cv::FileNode root = fs.root();
  if (!root.isMap()) in.Fail("(file)", "not a map of fields");
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
  const cv::FileNode stereo = in.Required(root, "stereo", "stereo");
  if (!stereo.isMap()) in.Fail("stereo", "not a map of fields");
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
