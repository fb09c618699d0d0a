#include "sim/sim_config.h"

#include <cmath>
#include <filesystem>
#include <limits>
#include <set>
#include <sstream>
#include <tuple>
#include <utility>
#include <vector>

#include <opencv2/calib3d.hpp>
#include <yaml-cpp/yaml.h>

#include "models/curve_fit.h"
#include "models/distortion_function.h"
#include "models/fisheye_lens.h"
#include "models/lens_table.h"
#include "models/model_registry.h"
#include "models/theia_lens.h"
#include "runtime/bounded_file.h"
#include "runtime/opencv_yaml.h"
#include "sim/ray_map.h"

namespace ws {
namespace {

namespace fs = std::filesystem;

std::string Join(const std::set<std::string>& names) {
  std::string out;
  for (const auto& name : names) out += (out.empty() ? "" : ", ") + name;
  return out;
}

std::string Show(const YAML::Node& node) {
  if (node.IsScalar()) return "'" + node.Scalar() + "'";
  if (node.IsSequence()) return "a list";
  if (node.IsMap()) return "a map";
  return "nothing";
}

std::string Number(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

// A YAML map whose fields are read one by one, each checked; Finish() rejects
// the fields nobody asked for.
class Fields {
 public:
  Fields(const YAML::Node& node, std::string path, const std::string& source)
      : node_(node), path_(std::move(path)), source_(source) {
    if (!node_.IsMap()) Fail(path_.empty() ? "the file" : path_, "must be a map of fields, not " + Show(node_));
  }

  [[noreturn]] void Fail(const std::string& field, const std::string& why) const {
    throw SimConfigError(source_ + ": " + field + ": " + why);
  }
  std::string Path(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

  bool Has(const std::string& key) {
    known_.insert(key);
    return bool(node_[key]);
  }
  YAML::Node Node(const std::string& key) {
    known_.insert(key);
    return node_[key];
  }
  Fields Map(const std::string& key) {
    known_.insert(key);
    return Fields(node_[key], Path(key), source_);
  }

  double Real(const std::string& key, double fallback, double min, double max,
              bool min_open = false) {
    if (!Has(key)) return fallback;
    return CheckReal(node_[key], Path(key), min, max, min_open);
  }
  double RequiredReal(const std::string& key, double min, double max, bool min_open = false) {
    if (!Has(key)) Fail(Path(key), "is required");
    return CheckReal(node_[key], Path(key), min, max, min_open);
  }
  int Whole(const std::string& key, int fallback, int min, int max) {
    if (!Has(key)) return fallback;
    return CheckWhole(node_[key], Path(key), min, max);
  }
  std::string Text(const std::string& key, const std::string& fallback) {
    if (!Has(key)) return fallback;
    const YAML::Node value = node_[key];
    if (!value.IsScalar()) Fail(Path(key), "must be text, not " + Show(value));
    return value.Scalar();
  }
  std::string Choice(const std::string& key, const std::string& fallback,
                     const std::set<std::string>& choices) {
    const std::string value = Text(key, fallback);
    if (!choices.count(value)) Fail(Path(key), "must be one of " + Join(choices) + ", not '" + value + "'");
    return value;
  }
  // A list of exactly n numbers within [min, max].
  std::vector<double> Reals(const std::string& key, size_t n, double min, double max) {
    const YAML::Node value = Node(key);
    if (!value.IsSequence() || value.size() != n)
      Fail(Path(key), "must be a list of " + std::to_string(n) + " numbers, not " + Show(value));
    std::vector<double> out;
    for (size_t i = 0; i < n; ++i)
      out.push_back(CheckReal(value[i], Path(key) + "[" + std::to_string(i) + "]", min, max, false));
    return out;
  }

  void Finish() const {
    for (const auto& item : node_) {
      const std::string key = item.first.Scalar();
      if (!known_.count(key))
        Fail(Path(key), "unknown field (known here: " + Join(known_) + ")");
    }
  }

  double CheckReal(const YAML::Node& value, const std::string& path, double min, double max,
                   bool min_open) const {
    double x = 0;
    bool ok = value.IsScalar();
    if (ok) {
      const std::string text = value.Scalar();
      size_t used = 0;
      try {
        x = std::stod(text, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      ok = used > 0 && used == text.size() && std::isfinite(x);
    }
    if (!ok) Fail(path, "must be a number, not " + Show(value));
    if (x < min || x > max || (min_open && x == min))
      Fail(path, "must be " + RangeText(min, max, min_open) + ", not " + value.Scalar());
    return x;
  }
  int CheckWhole(const YAML::Node& value, const std::string& path, int min, int max) const {
    long x = 0;
    bool ok = value.IsScalar();
    if (ok) {
      const std::string text = value.Scalar();
      size_t used = 0;
      try {
        x = std::stol(text, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      ok = used > 0 && used == text.size();
    }
    if (!ok) Fail(path, "must be a whole number, not " + Show(value));
    if (x < min || x > max)
      Fail(path, "must be a whole number from " + std::to_string(min) + " to " + std::to_string(max) +
                     ", not " + value.Scalar());
    return int(x);
  }

 private:
  static std::string RangeText(double min, double max, bool min_open) {
    const bool no_max = max == std::numeric_limits<double>::max();
    if (no_max) return std::string(min_open ? "greater than " : "at least ") + Number(min);
    return std::string(min_open ? "greater than " : "from ") + Number(min) +
           (min_open ? " and at most " : " to ") + Number(max);
  }

  YAML::Node node_;
  std::string path_;
  const std::string& source_;
  std::set<std::string> known_;
};

constexpr double kBig = std::numeric_limits<double>::max();

std::vector<double> ParseCoefficients(Fields& fields, const std::string& field, const std::string& text,
                                      size_t n) {
  std::vector<double> out;
  std::stringstream stream(text);
  std::string part;
  while (std::getline(stream, part, ',')) {
    size_t used = 0;
    double value = 0;
    try {
      value = std::stod(part, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != part.size() || !std::isfinite(value))
      fields.Fail(field, "coefficient '" + part + "' is not a number");
    out.push_back(value);
  }
  if (out.size() != n)
    fields.Fail(field, "needs " + std::to_string(n) + " comma-separated coefficients, got " +
                           std::to_string(out.size()));
  return out;
}

// Every pixel of the image inside the lens's image circle must see a ray:
// checked along the circle (rays max_theta off axis, when the lens has one)
// and along the image border (the radius grows outwards, so the border is
// where a lens folds first); border pixels past the circle see nothing.
void CheckInvertible(Fields& fields, const std::string& path, const CameraModel& model, double max_theta) {
  const Camera camera(model);
  const int w = model.image_width, h = model.image_height;
  auto fail = [&](const cv::Point2d& p) {
    fields.Fail(path, "the lens model cannot be inverted at pixel (" + Number(p.x) + ", " + Number(p.y) +
                          "): its distortion curve folds inside the image (a field too wide for the model?)");
  };
  // The smallest normalized distorted radius of the circle: pixels nearer the centre are inside it.
  auto radius = [&](const cv::Point2d& p) { return std::hypot((p.x - model.cx) / model.fx, (p.y - model.cy) / model.fy); };
  double circle = std::numeric_limits<double>::infinity();
  if (max_theta < M_PI)
    for (const Eigen::Vector3d& ray : RaysAround(max_theta, 64)) {
      const auto pixel = camera.Project(ray);
      if (!pixel) fields.Fail(path, "the lens model has no pixel for rays " + Number(max_theta * 180 / M_PI) +
                                        " degrees off axis (field_deg too wide for the model)");
      const cv::Point2d p((*pixel)[0], (*pixel)[1]);
      if (!camera.Unproject(*pixel)) fail(p);
      circle = std::min(circle, radius(p));
    }
  std::vector<cv::Point2d> border;
  for (int i = 0; i <= 64; ++i) {
    const double s = i / 64.0;
    border.push_back({s * (w - 1) + (1 - s) * -0.5, -0.5});
    border.push_back({s * (w - 1) + (1 - s) * -0.5, h - 0.5});
    border.push_back({-0.5, s * (h - 1) + (1 - s) * -0.5});
    border.push_back({w - 0.5, s * (h - 1) + (1 - s) * -0.5});
  }
  for (const auto& p : border)
    if (radius(p) < circle && !camera.Unproject({p.x, p.y})) fail(p);
}

// The camera and its half field (radians) from a camera entry.
std::pair<CameraModel, double> ParseCamera(Fields fields, const std::string& base_dir) {
  const std::string lens = fields.Text("lens", "theia");
  if (lens == "fisheye-knee")
    for (const char* own : {"fit", "focal_length_mm", "pixel_pitch_mm", "image_size"})
      if (fields.Has(own))
        fields.Fail(fields.Path(own), "the fisheye-knee lens has its own (override fx, fy, cx, cy instead)");
  const ModelKind fit = ParseModelKind(fields.Choice("fit", "bspline", {"bspline", "poly6", "poly12"}));
  const double focal_mm = fields.Real("focal_length_mm", 1.3, 0, kBig, true);
  const double pitch_mm = fields.Real("pixel_pitch_mm", 0.00375, 0, kBig, true);
  int width = 1280, height = 960;
  if (fields.Has("image_size")) {
    const YAML::Node size = fields.Node("image_size");
    if (!size.IsSequence() || size.size() != 2)
      fields.Fail(fields.Path("image_size"), "must be [WIDTH, HEIGHT], not " + Show(size));
    width = fields.CheckWhole(size[0], fields.Path("image_size[0]"), 16, 16384);
    height = fields.CheckWhole(size[1], fields.Path("image_size[1]"), 16, 16384);
  }

  const std::string lens_path = fields.Path("lens");
  const size_t colon = lens.find(':');
  const std::string kind = lens.substr(0, colon);
  const std::string arg = colon == std::string::npos ? "" : lens.substr(colon + 1);
  CameraModel model;
  double field_deg = 360;
  if (lens == "fisheye-knee") {
    model = FisheyeKneeCamera();
    field_deg = 200;
  } else if (kind == "theia" || kind == "table" || kind == "table-percent") {
    if ((kind == "theia") != arg.empty())
      fields.Fail(lens_path, "'" + lens + "' is not theia, table:PATH or table-percent:PATH");
    LensTable table;
    if (kind == "theia") {
      table = TheiaLikeLensTable();
    } else {
      const fs::path path = fs::path(arg).is_absolute() ? fs::path(arg) : fs::path(base_dir) / arg;
      try {
        table = ReadLensTable(path.string(), kind == "table" ? TableColumns::kRealHeight : TableColumns::kPercent);
      } catch (const std::exception& e) {
        fields.Fail(lens_path, e.what());
      }
    }
    LensSensor sensor;
    sensor.focal_length_mm = focal_mm;
    sensor.pixel_pitch_mm = pitch_mm;
    sensor.image_width = width;
    sensor.image_height = height;
    try {
      model = CameraFromLensTable(table, sensor);
      if (fit != ModelKind::kBspline) {
        const LensTable normalized = ScaleLensTable(table, 1.0 / focal_mm);
        model.distortion = FitByLeastSquares(MakeModel(Distortion{fit, 0, {}, {}}, Coefficients::kAll),
                                             normalized);
      }
    } catch (const std::exception& e) {
      fields.Fail(lens_path, "cannot fit " + ModelName(fit) + " to the table: " + e.what());
    }
  } else if (kind == "poly6" || kind == "poly12") {
    const ModelKind poly = ParseModelKind(kind);
    if (fields.Has("fit") && fit != poly)
      fields.Fail(fields.Path("fit"), "applies to table lenses only");
    model.image_width = width;
    model.image_height = height;
    model.fx = model.fy = focal_mm / pitch_mm;
    model.cx = width / 2.0;
    model.cy = height / 2.0;
    model.distortion = Distortion{poly, 0, {}, ParseCoefficients(fields, lens_path, arg, Traits(poly).terms)};
  } else {
    fields.Fail(lens_path, "must be theia, fisheye-knee, table:PATH, table-percent:PATH, poly6:k1,k2,k3 or "
                           "poly12:k1,...,k6, not '" + lens + "'");
  }
  model.fx = fields.Real("fx", model.fx, 0, kBig, true);
  model.fy = fields.Real("fy", model.fy, 0, kBig, true);
  model.cx = fields.Real("cx", model.cx, -kBig, kBig);
  model.cy = fields.Real("cy", model.cy, -kBig, kBig);
  model.p1 = fields.Real("p1", 0, -0.1, 0.1);
  model.p2 = fields.Real("p2", 0, -0.1, 0.1);
  if (fields.Has("sensor_tilt_deg")) {
    const std::vector<double> tilt = fields.Reals("sensor_tilt_deg", 2, -5, 5);
    model.nonradial.tilt = {tilt[0] * M_PI / 180, tilt[1] * M_PI / 180};
  }
  const bool angle = Traits(model.distortion.kind).angle;
  field_deg = fields.Real("field_deg", field_deg, 0, angle ? 360 : 180, true);
  if (!angle && field_deg == 180)
    fields.Fail(fields.Path("field_deg"), "a pinhole model (" + ModelName(model.distortion.kind) + ") sees less than 180 degrees");
  fields.Finish();
  const double max_theta = std::min(M_PI, field_deg / 2 * M_PI / 180);
  try {
    CheckInvertible(fields, lens_path, model, max_theta);
  } catch (const std::invalid_argument& e) {
    fields.Fail(lens_path, e.what());
  }
  return {model, max_theta};
}

cv::Matx33d RotationDeg(const std::vector<double>& degrees) {
  cv::Matx33d R;
  cv::Rodrigues(cv::Vec3d(degrees[0], degrees[1], degrees[2]) * (CV_PI / 180), R);
  return R;
}

SimBoardScene ParseBoard(Fields fields) {
  SimBoardScene scene;
  const std::string spec = fields.Text("spec", "");
  if (spec.empty()) fields.Fail(fields.Path("spec"), "is required (e.g. chessboard:9x6:0.05)");
  try {
    scene.board = ParseBoardSpec(spec);
  } catch (const std::invalid_argument& e) {
    fields.Fail(fields.Path("spec"), e.what());
  }
  scene.poses = fields.Whole("poses", scene.poses, 1, 100000);
  if (fields.Has("depth")) {
    const auto depth = fields.Reals("depth", 2, 0.05, 100);
    if (depth[0] > depth[1]) fields.Fail(fields.Path("depth"), "must be [MIN, MAX] with MIN <= MAX");
    scene.depth_min = depth[0];
    scene.depth_max = depth[1];
  }
  scene.max_tilt_deg = fields.Real("max_tilt_deg", scene.max_tilt_deg, 0, 70);
  scene.max_roll_deg = fields.Real("max_roll_deg", scene.max_roll_deg, 0, 180);
  if (fields.Has("grid")) {
    const YAML::Node grid = fields.Node("grid");
    if (!grid.IsSequence() || grid.size() != 2)
      fields.Fail(fields.Path("grid"), "must be [COLS, ROWS], not " + Show(grid));
    scene.grid_cols = fields.CheckWhole(grid[0], fields.Path("grid[0]"), 1, 100);
    scene.grid_rows = fields.CheckWhole(grid[1], fields.Path("grid[1]"), 1, 100);
  }
  const std::string targets = fields.Choice("targets", "both", {"both", "left", "right"});
  scene.targets = targets == "both"   ? SimBoardScene::Targets::both
                  : targets == "left" ? SimBoardScene::Targets::left
                                      : SimBoardScene::Targets::right;
  scene.edge_margin_px = fields.Real("edge_margin_px", scene.edge_margin_px, -10000, 1000);
  fields.Finish();
  return scene;
}

SimWallScene ParseWall(Fields fields) {
  SimWallScene wall;
  wall.frames = fields.Whole("frames", wall.frames, 1, 100000);
  wall.distance = fields.Real("distance", wall.distance, 0, 1000, true);
  if (fields.Has("tilt_deg")) {
    const auto tilt = fields.Reals("tilt_deg", 2, -60, 60);
    wall.tilt_x_deg = tilt[0];
    wall.tilt_y_deg = tilt[1];
  }
  wall.dot_size = fields.Real("dot_size", wall.dot_size, 0, 100, true);
  wall.density = fields.Real("density", wall.density, 0, 1);
  fields.Finish();
  return wall;
}

SimRoomScene ParseRoom(Fields fields, const SimConfig& config) {
  SimRoomScene room;
  room.frames = fields.Whole("frames", room.frames, 1, 100000);
  if (fields.Has("size")) {
    const auto size = fields.Reals("size", 3, 0, 1000);
    room.size = cv::Vec3d(size[0], size[1], size[2]);
    if (!(size[0] > 0 && size[1] > 0 && size[2] > 0)) fields.Fail(fields.Path("size"), "must be positive");
  }
  if (fields.Has("centre")) {
    const auto centre = fields.Reals("centre", 3, -1000, 1000);
    room.centre = cv::Vec3d(centre[0], centre[1], centre[2]);
  }
  // Both camera centres inside: the left at the origin, the right at -R^T T.
  for (const cv::Vec3d& camera : {cv::Vec3d(0, 0, 0), cv::Vec3d(-(config.R.t() * config.T))})
    for (int axis = 0; axis < 3; ++axis)
      if (!(std::abs(camera[axis] - room.centre[axis]) < room.size[axis] / 2))
        fields.Fail(fields.Path("centre"), "both cameras must be inside the room");
  room.dot_size = fields.Real("dot_size", room.dot_size, 0, 100, true);
  room.density = fields.Real("density", room.density, 0, 1);
  fields.Finish();
  return room;
}

SimRendering ParseRendering(Fields fields) {
  SimRendering r;
  r.supersample = fields.Whole("supersample", r.supersample, 1, 16);
  r.blur_sigma = fields.Real("blur_sigma", r.blur_sigma, 0, 20);
  r.noise_sigma = fields.Real("noise_sigma", r.noise_sigma, 0, 100);
  r.black = fields.Real("black", r.black, 0, 255);
  r.white = fields.Real("white", r.white, 0, 255);
  r.background = fields.Real("background", r.background, 0, 255);
  r.gamma = fields.Real("gamma", r.gamma, 0.1, 10);
  if (r.black >= r.white) fields.Fail(fields.Path("white"), "must be greater than black");
  fields.Finish();
  return r;
}

}  // namespace

SimConfig ParseSimConfig(const std::string& yaml, const std::string& source, const std::string& base_dir) {
  YAML::Node root;
  try {
    root = YAML::Load(yaml);
  } catch (const YAML::Exception& e) {
    throw SimConfigError(source + ": not valid YAML: " + e.what());
  }
  SimConfig config;
  config.source = source;
  Fields top(root, "", source);
  const YAML::Node seed = top.Node("seed");
  if (seed) {
    const long value = top.CheckWhole(seed, "seed", 0, std::numeric_limits<int>::max());
    config.seed = uint64_t(value);
  }
  config.truth_path = top.Text("truth", "");

  if (!top.Has("rig")) top.Fail("rig", "is required");
  Fields rig = top.Map("rig");
  if (!rig.Has("left")) rig.Fail("rig.left", "is required (the left camera)");
  std::tie(config.left, config.max_theta[0]) = ParseCamera(rig.Map("left"), base_dir);
  std::tie(config.right, config.max_theta[1]) =
      rig.Has("right") ? ParseCamera(rig.Map("right"), base_dir) : std::pair(config.left, config.max_theta[0]);
  config.R = rig.Has("rotation_deg") ? RotationDeg(rig.Reals("rotation_deg", 3, -30, 30)) : cv::Matx33d::eye();
  if (rig.Has("T")) {
    if (rig.Has("baseline")) rig.Fail("rig.T", "give either baseline or T, not both");
    const auto T = rig.Reals("T", 3, -100, 100);
    config.T = cv::Vec3d(T[0], T[1], T[2]);
    if (cv::norm(config.T) == 0) rig.Fail("rig.T", "the cameras must not be at one place");
  } else {
    const double baseline = rig.RequiredReal("baseline", 0, 100, true);
    config.T = -(config.R * cv::Vec3d(baseline, 0, 0));
  }
  rig.Finish();

  if (!top.Has("scene")) top.Fail("scene", "is required (a board, a wall or a room)");
  Fields scene = top.Map("scene");
  if (scene.Has("board")) config.board = ParseBoard(scene.Map("board"));
  if (scene.Has("wall")) config.wall = ParseWall(scene.Map("wall"));
  if (scene.Has("room")) config.room = ParseRoom(scene.Map("room"), config);
  if (!config.board && !config.wall && !config.room) scene.Fail("scene", "needs a board, a wall or a room");
  scene.Finish();

  if (top.Has("rendering")) config.rendering = ParseRendering(top.Map("rendering"));
  top.Finish();
  return config;
}

SimConfig LoadSimConfig(const std::string& path) {
  std::string text;
  try {
    text = ReadBoundedFile(path, kMaxYamlFileBytes);
  } catch (const BoundedFileError& e) {
    throw SimConfigError(path + ": cannot read the simulator config: " + e.what());
  }
  const fs::path parent = fs::path(path).parent_path();
  return ParseSimConfig(text, path, parent.empty() ? "." : parent.string());
}

CameraModel SimDefaultCamera(double scale) {
  LensSensor sensor;
  sensor.image_width = int(std::lround(sensor.image_width * scale));
  sensor.image_height = int(std::lround(sensor.image_height * scale));
  sensor.pixel_pitch_mm /= scale;
  return CameraFromLensTable(TheiaLikeLensTable(), sensor);
}

SimConfig DefaultSimConfig(double scale) {
  SimConfig config;
  config.source = "DefaultSimConfig";
  config.left = config.right = SimDefaultCamera(scale);
  config.R = cv::Matx33d::eye();
  config.T = cv::Vec3d(-0.3, 0, 0);
  config.board.emplace();
  config.board->board = ParseBoardSpec("chessboard:9x6:0.05");
  config.wall.emplace();
  return config;
}

}  // namespace ws
