#include "sim/ground_truth.h"

#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "models/model_registry.h"
#include "runtime/opencv_yaml.h"

namespace ws {
namespace {

void WriteCamera(cv::FileStorage& fs, const std::string& name, const CameraModel& m, double max_theta) {
  fs << "{";
  fs << "name" << name;
  fs << "kind" << ModelName(m.distortion.kind);
  fs << "degree" << m.distortion.degree;
  fs << "knots" << m.distortion.knots;
  fs << Traits(m.distortion.kind).coeff_key << m.distortion.coeffs;
  fs << "fx" << m.fx << "fy" << m.fy << "cx" << m.cx << "cy" << m.cy << "p1" << m.p1 << "p2" << m.p2;
  fs << "image_width" << m.image_width << "image_height" << m.image_height;
  if (m.nonradial.tilted())  // a tilted sensor (models/sensor_tilt.h)
    fs << "sensor_tilt" << std::vector<double>(m.nonradial.tilt.begin(), m.nonradial.tilt.end());
  if (m.nonradial.cols > 0)
    fs << "nonradial_cols" << m.nonradial.cols << "nonradial_rows" << m.nonradial.rows
       << "nonradial_domain" << std::vector<double>(m.nonradial.domain.begin(), m.nonradial.domain.end())
       << "nonradial_coeffs" << m.nonradial.coeffs;
  fs << "K" << cv::Mat(cv::Matx33d(m.fx, 0, m.cx, 0, m.fy, m.cy, 0, 0, 1));
  fs << "field_deg" << 2 * max_theta * 180 / M_PI;
  fs << "}";
}

void WriteView(cv::FileStorage& fs, const std::string& name, const SimViewTruth& view) {
  fs << name << "{";
  fs << "view" << BoardViewName(view.view);
  cv::Mat corners(int(view.corners.size()), 2, CV_64FC1);
  for (int i = 0; i < corners.rows; ++i) {
    corners.at<double>(i, 0) = view.corners[i].x;
    corners.at<double>(i, 1) = view.corners[i].y;
  }
  fs << "corners" << corners;
  std::vector<int> in_image(view.in_image.begin(), view.in_image.end());
  fs << "in_image" << in_image;
  fs << "}";
}

class Reader {
 public:
  explicit Reader(const std::string& path) : path_(path) {}
  [[noreturn]] void Fail(const std::string& field, const std::string& why) const {
    throw std::runtime_error(path_ + ": " + field + ": " + why);
  }
  cv::FileNode Need(const cv::FileNode& parent, const std::string& key, const std::string& where) const {
    const cv::FileNode node = parent[key];
    if (node.isNone()) Fail(where + key, "is missing");
    return node;
  }
  double Real(const cv::FileNode& parent, const std::string& key, const std::string& where) const {
    const cv::FileNode node = Need(parent, key, where);
    if (!node.isReal() && !node.isInt()) Fail(where + key, "is not a number");
    return double(node);
  }
  int Int(const cv::FileNode& parent, const std::string& key, const std::string& where) const {
    const cv::FileNode node = Need(parent, key, where);
    if (!node.isInt()) Fail(where + key, "is not a whole number");
    return int(node);
  }
  std::string Text(const cv::FileNode& parent, const std::string& key, const std::string& where) const {
    const cv::FileNode node = Need(parent, key, where);
    if (!node.isString()) Fail(where + key, "is not text");
    return std::string(node);
  }
  std::vector<double> Reals(const cv::FileNode& parent, const std::string& key, const std::string& where) const {
    const cv::FileNode node = Need(parent, key, where);
    if (!node.isSeq()) Fail(where + key, "is not a list");
    std::vector<double> out;
    for (const auto& item : node) {
      if (!item.isReal() && !item.isInt()) Fail(where + key, "holds something that is not a number");
      out.push_back(double(item));
    }
    return out;
  }
  cv::Mat Matrix(const cv::FileNode& parent, const std::string& key, const std::string& where, int rows,
                 int cols) const {
    cv::Mat m;
    Need(parent, key, where) >> m;
    if (m.empty() && rows * cols != 0) Fail(where + key, "is not a matrix");
    if (rows >= 0 && m.rows != rows) Fail(where + key, "must have " + std::to_string(rows) + " rows");
    if (m.cols != cols && !(m.empty() && rows == 0)) Fail(where + key, "must have " + std::to_string(cols) + " columns");
    m.convertTo(m, CV_64F);
    return m;
  }

 private:
  std::string path_;
};

// The camera, and its half field (radians) from field_deg (pi without one).
CameraModel ReadCamera(const Reader& r, const cv::FileNode& node, const std::string& where, double* max_theta) {
  *max_theta = M_PI;
  if (!node["field_deg"].isNone()) {
    const double field_deg = r.Real(node, "field_deg", where);
    if (!(field_deg > 0 && field_deg <= 360)) r.Fail(where + "field_deg", "must be greater than 0 and at most 360");
    *max_theta = field_deg / 2 * M_PI / 180;
  }
  CameraModel m;
  m.distortion.kind = ParseModelKind(r.Text(node, "kind", where));
  m.distortion.degree = r.Int(node, "degree", where);
  m.distortion.knots = r.Reals(node, "knots", where);
  m.distortion.coeffs = r.Reals(node, Traits(m.distortion.kind).coeff_key, where);
  m.fx = r.Real(node, "fx", where);
  m.fy = r.Real(node, "fy", where);
  m.cx = r.Real(node, "cx", where);
  m.cy = r.Real(node, "cy", where);
  m.p1 = r.Real(node, "p1", where);
  m.p2 = r.Real(node, "p2", where);
  m.image_width = r.Int(node, "image_width", where);
  m.image_height = r.Int(node, "image_height", where);
  if (!node["sensor_tilt"].isNone()) {
    const std::vector<double> tilt = r.Reals(node, "sensor_tilt", where);
    if (tilt.size() != 2) r.Fail(where + "sensor_tilt", "must be 2 numbers");
    std::copy(tilt.begin(), tilt.end(), m.nonradial.tilt.begin());
  }
  if (!node["nonradial_cols"].isNone()) {
    m.nonradial.cols = r.Int(node, "nonradial_cols", where);
    m.nonradial.rows = r.Int(node, "nonradial_rows", where);
    const std::vector<double> domain = r.Reals(node, "nonradial_domain", where);
    if (domain.size() != 4) r.Fail(where + "nonradial_domain", "must be 4 numbers");
    std::copy(domain.begin(), domain.end(), m.nonradial.domain.begin());
    m.nonradial.coeffs = r.Reals(node, "nonradial_coeffs", where);
  }
  try {
    NonRadialField::FromData(m.nonradial);
    Camera camera(m);
  } catch (const std::exception& e) {
    r.Fail(where.substr(0, where.size() - 1), std::string("not a valid camera model: ") + e.what());
  }
  return m;
}

SimViewTruth ReadView(const Reader& r, const cv::FileNode& node, const std::string& where, int corners) {
  SimViewTruth view;
  const std::string name = r.Text(node, "view", where);
  if (name == "full") view.view = BoardView::full;
  else if (name == "partial") view.view = BoardView::partial;
  else if (name == "none") view.view = BoardView::none;
  else r.Fail(where + "view", "must be full, partial or none, not '" + name + "'");
  const cv::Mat m = r.Matrix(node, "corners", where, corners, 2);
  for (int i = 0; i < m.rows; ++i) view.corners.emplace_back(m.at<double>(i, 0), m.at<double>(i, 1));
  for (double v : r.Reals(node, "in_image", where)) view.in_image.push_back(v != 0);
  if (int(view.in_image.size()) != corners) r.Fail(where + "in_image", "must have one entry per corner");
  return view;
}

}  // namespace

const char* BoardViewName(BoardView view) {
  switch (view) {
    case BoardView::full: return "full";
    case BoardView::partial: return "partial";
    case BoardView::none: return "none";
  }
  return "none";
}

void WriteSimTruth(const std::string& path, const SimTruth& truth) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  std::error_code error;
  if (!parent.empty()) std::filesystem::create_directories(parent, error);
  cv::FileStorage fs;
  try {
    fs.open(path, cv::FileStorage::WRITE | cv::FileStorage::FORMAT_YAML);
  } catch (const cv::Exception& e) {
    throw std::runtime_error("cannot write the simulator's ground truth " + path + ": " + e.what());
  }
  if (!fs.isOpened()) throw std::runtime_error("cannot write the simulator's ground truth " + path);
  fs.writeComment("widestereo simulator ground truth (common/sim/ground_truth.h)");
  fs << "config" << truth.config;
  fs << "seed" << std::to_string(truth.seed);
  fs << "cameras" << "[";
  WriteCamera(fs, "left", truth.left, truth.max_theta[0]);
  WriteCamera(fs, "right", truth.right, truth.max_theta[1]);
  fs << "]";
  fs.writeComment("X_right = R X_left + T, metres");
  fs << "R" << cv::Mat(truth.R) << "T" << cv::Mat(truth.T);
  fs << "board" << truth.board;
  const SimRendering& r = truth.rendering;
  fs << "rendering" << "{" << "supersample" << r.supersample << "blur_sigma" << r.blur_sigma << "noise_sigma"
     << r.noise_sigma << "black" << r.black << "white" << r.white << "background" << r.background << "gamma"
     << r.gamma << "}";
  fs << "frames" << "[";
  for (const auto& f : truth.frames) {
    fs << "{";
    fs << "index" << f.index << "kind" << f.kind;
    fs << "R" << cv::Mat(f.R) << "t" << cv::Mat(f.t);
    if (f.kind == "board") {
      fs << "target" << f.target;
      WriteView(fs, "left", f.left);
      WriteView(fs, "right", f.right);
    } else if (f.kind == "room") {
      std::vector<double> planes;
      for (const cv::Vec4d& plane : f.room_planes) planes.insert(planes.end(), plane.val, plane.val + 4);
      fs << "room_planes" << planes;
    } else {
      fs << "wall_distance" << f.wall_distance;
      fs << "wall_normal" << std::vector<double>{f.wall_normal[0], f.wall_normal[1], f.wall_normal[2]};
      fs << "wall_offset" << f.wall_offset;
    }
    fs << "}";
  }
  fs << "]";
  fs.release();
}

SimTruth LoadSimTruth(const std::string& path) {
  cv::FileStorage fs;
  try {
    OpenOpenCvYaml(fs, path);
  } catch (const YamlFileError& e) {
    throw std::runtime_error(path + ": not a ground-truth file: " + e.what());
  }
  const Reader r(path);
  const cv::FileNode root = fs.root();
  SimTruth truth;
  truth.config = r.Text(root, "config", "");
  try {
    truth.seed = std::stoull(r.Text(root, "seed", ""));
  } catch (const std::logic_error&) {
    r.Fail("seed", "is not a whole number");
  }
  const cv::FileNode cameras = root["cameras"];
  if (!cameras.isSeq() || cameras.size() != 2) r.Fail("cameras", "must list the left and the right camera");
  truth.left = ReadCamera(r, cameras[0], "cameras[0].", &truth.max_theta[0]);
  truth.right = ReadCamera(r, cameras[1], "cameras[1].", &truth.max_theta[1]);
  truth.R = cv::Matx33d(r.Matrix(root, "R", "", 3, 3));
  truth.T = cv::Vec3d(r.Matrix(root, "T", "", 3, 1));
  truth.board = r.Text(root, "board", "");
  int corner_count = 0;
  if (!truth.board.empty()) {
    try {
      corner_count = ParseBoardSpec(truth.board).corner_count();
    } catch (const std::exception& e) {
      r.Fail("board", e.what());
    }
  }
  const cv::FileNode rendering = r.Need(root, "rendering", "");
  truth.rendering.supersample = r.Int(rendering, "supersample", "rendering.");
  truth.rendering.blur_sigma = r.Real(rendering, "blur_sigma", "rendering.");
  truth.rendering.noise_sigma = r.Real(rendering, "noise_sigma", "rendering.");
  truth.rendering.black = r.Real(rendering, "black", "rendering.");
  truth.rendering.white = r.Real(rendering, "white", "rendering.");
  truth.rendering.background = r.Real(rendering, "background", "rendering.");
  truth.rendering.gamma = r.Real(rendering, "gamma", "rendering.");
  const cv::FileNode frames = root["frames"];
  if (!frames.isSeq()) r.Fail("frames", "must be a list");
  int i = 0;
  for (const auto& node : frames) {
    const std::string where = "frames[" + std::to_string(i++) + "].";
    SimFrameTruth f;
    f.index = r.Int(node, "index", where);
    f.kind = r.Text(node, "kind", where);
    f.R = cv::Matx33d(r.Matrix(node, "R", where, 3, 3));
    f.t = cv::Vec3d(r.Matrix(node, "t", where, 3, 1));
    if (f.kind == "board") {
      if (truth.board.empty()) r.Fail(where + "kind", "a board frame in a file without a board");
      f.target = r.Text(node, "target", where);
      f.left = ReadView(r, r.Need(node, "left", where), where + "left.", corner_count);
      f.right = ReadView(r, r.Need(node, "right", where), where + "right.", corner_count);
    } else if (f.kind == "wall") {
      f.wall_distance = r.Real(node, "wall_distance", where);
      const auto normal = r.Reals(node, "wall_normal", where);
      if (normal.size() != 3) r.Fail(where + "wall_normal", "must hold 3 numbers");
      f.wall_normal = cv::Vec3d(normal[0], normal[1], normal[2]);
      f.wall_offset = r.Real(node, "wall_offset", where);
    } else if (f.kind == "room") {
      const auto planes = r.Reals(node, "room_planes", where);
      if (planes.size() != 24) r.Fail(where + "room_planes", "must hold 6 planes of 4 numbers");
      for (size_t k = 0; k < planes.size(); k += 4)
        f.room_planes.emplace_back(planes[k], planes[k + 1], planes[k + 2], planes[k + 3]);
    } else {
      r.Fail(where + "kind", "must be board, wall or room, not '" + f.kind + "'");
    }
    truth.frames.push_back(f);
  }
  return truth;
}

}  // namespace ws
