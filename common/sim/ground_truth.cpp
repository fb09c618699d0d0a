#include "sim/ground_truth.h"

#include <cmath>
#include <filesystem>
#include <stdexcept>

#include <opencv2/core/eigen.hpp>

#include "rig/camera_fields.h"
#include "runtime/opencv_yaml.h"

namespace ws {
namespace {

// A camera as the calibration file holds it (rig/camera_fields.h), with
// its name and its lens's field.
void WriteCamera(cv::FileStorage& fs, const std::string& name, const CameraModel& m, double max_theta) {
  fs << "{";
  fs << "name" << name;
  WriteCameraFields(fs, m);
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

// The camera, and its half field (radians) from field_deg (pi without one).
CameraModel ReadCamera(const YamlReader& in, const cv::FileNode& node, const std::string& at, double* max_theta) {
  if (!node.isMap()) in.Fail(at.substr(0, at.size() - 1), "not a map of camera fields");
  *max_theta = M_PI;
  if (!node["field_deg"].empty()) {
    const double field_deg = in.Real(node, "field_deg", at + "field_deg");
    if (!(field_deg > 0 && field_deg <= 360)) in.Fail(at + "field_deg", "must be greater than 0 and at most 360");
    *max_theta = field_deg / 2 * M_PI / 180;
  }
  return ReadCameraFields(in, node, at);
}

cv::Matx33d Rotation(const YamlReader& in, const cv::FileNode& node, const std::string& key, const std::string& at) {
  const Eigen::MatrixXd R = in.Matrix(node, key, at + key, 3, 3);
  return cv::Matx33d(R(0, 0), R(0, 1), R(0, 2), R(1, 0), R(1, 1), R(1, 2), R(2, 0), R(2, 1), R(2, 2));
}

cv::Vec3d Vector(const YamlReader& in, const cv::FileNode& node, const std::string& key, const std::string& at) {
  const Eigen::MatrixXd t = in.Matrix(node, key, at + key, 3, 1);
  return cv::Vec3d(t(0), t(1), t(2));
}

SimViewTruth ReadView(const YamlReader& in, const cv::FileNode& node, const std::string& at, int corners) {
  SimViewTruth view;
  const std::string name = in.String(node, "view", at + "view");
  if (name == "full") view.view = BoardView::full;
  else if (name == "partial") view.view = BoardView::partial;
  else if (name == "none") view.view = BoardView::none;
  else in.Fail(at + "view", "must be full, partial or none, not '" + name + "'");
  const Eigen::MatrixXd m = in.Matrix(node, "corners", at + "corners", corners, 2);
  for (int i = 0; i < m.rows(); ++i) view.corners.emplace_back(m(i, 0), m(i, 1));
  for (double v : in.Reals(node, "in_image", at + "in_image", size_t(corners))) view.in_image.push_back(v != 0);
  if (int(view.in_image.size()) != corners) in.Fail(at + "in_image", "must have one entry per corner");
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
  WriteCamera(fs, "left", truth.rig.left, truth.max_theta[0]);
  WriteCamera(fs, "right", truth.rig.right, truth.max_theta[1]);
  fs << "]";
  fs.writeComment("X_right = R X_left + T, metres");
  cv::Mat R, T;
  cv::eigen2cv(truth.rig.R, R);
  cv::eigen2cv(truth.rig.T, T);
  fs << "R" << R << "T" << T;
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
  const YamlReader in(path, "with the simulator (sim:CONFIG?truth=FILE)");
  cv::FileStorage fs;
  const cv::FileNode root = in.Open(fs, kMaxYamlFileBytes);
  SimTruth truth;
  truth.config = in.String(root, "config", "config");
  try {
    truth.seed = std::stoull(in.String(root, "seed", "seed"));
  } catch (const std::logic_error&) {
    in.Fail("seed", "is not a whole number");
  }
  const cv::FileNode cameras = root["cameras"];
  if (!cameras.isSeq() || cameras.size() != 2) in.Fail("cameras", "must list the left and the right camera");
  truth.rig.left = ReadCamera(in, cameras[0], "cameras[0].", &truth.max_theta[0]);
  truth.rig.right = ReadCamera(in, cameras[1], "cameras[1].", &truth.max_theta[1]);
  truth.rig.R = in.Matrix(root, "R", "R", 3, 3);
  truth.rig.T = in.Matrix(root, "T", "T", 3, 1);
  truth.board = in.String(root, "board", "board");
  int corner_count = 0;
  if (!truth.board.empty()) {
    try {
      corner_count = ParseBoardSpec(truth.board).corner_count();
    } catch (const std::exception& e) {
      in.Fail("board", e.what());
    }
  }
  const cv::FileNode rendering = in.Map(root, "rendering", "rendering");
  SimRendering& r = truth.rendering;
  r.supersample = in.Int(rendering, "supersample", "rendering.supersample", 1);
  r.blur_sigma = in.Real(rendering, "blur_sigma", "rendering.blur_sigma");
  r.noise_sigma = in.Real(rendering, "noise_sigma", "rendering.noise_sigma");
  r.black = in.Real(rendering, "black", "rendering.black");
  r.white = in.Real(rendering, "white", "rendering.white");
  r.background = in.Real(rendering, "background", "rendering.background");
  r.gamma = in.Real(rendering, "gamma", "rendering.gamma");
  const cv::FileNode frames = root["frames"];
  if (!frames.isSeq()) in.Fail("frames", "must be a list");
  for (const auto& node : frames) {
    const std::string at = "frames[" + std::to_string(truth.frames.size()) + "].";
    if (!node.isMap()) in.Fail(at.substr(0, at.size() - 1), "not a map of fields");
    SimFrameTruth f;
    f.index = in.Int(node, "index", at + "index", 0);
    f.kind = in.String(node, "kind", at + "kind");
    f.R = Rotation(in, node, "R", at);
    f.t = Vector(in, node, "t", at);
    if (f.kind == "board") {
      if (truth.board.empty()) in.Fail(at + "kind", "a board frame in a file without a board");
      f.target = in.String(node, "target", at + "target");
      f.left = ReadView(in, in.Map(node, "left", at + "left"), at + "left.", corner_count);
      f.right = ReadView(in, in.Map(node, "right", at + "right"), at + "right.", corner_count);
    } else if (f.kind == "wall") {
      f.wall_distance = in.Real(node, "wall_distance", at + "wall_distance");
      const std::vector<double> normal = in.Reals(node, "wall_normal", at + "wall_normal", 3);
      if (normal.size() != 3) in.Fail(at + "wall_normal", "must hold 3 numbers");
      f.wall_normal = cv::Vec3d(normal[0], normal[1], normal[2]);
      f.wall_offset = in.Real(node, "wall_offset", at + "wall_offset");
    } else if (f.kind == "room") {
      const std::vector<double> planes = in.Reals(node, "room_planes", at + "room_planes", 24);
      if (planes.size() != 24) in.Fail(at + "room_planes", "must hold 6 planes of 4 numbers");
      for (size_t k = 0; k < planes.size(); k += 4)
        f.room_planes.emplace_back(planes[k], planes[k + 1], planes[k + 2], planes[k + 3]);
    } else {
      in.Fail(at + "kind", "must be board, wall or room, not '" + f.kind + "'");
    }
    truth.frames.push_back(f);
  }
  return truth;
}

}  // namespace ws
