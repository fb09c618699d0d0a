#include "sim/simulator.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>

#include <opencv2/calib3d.hpp>

#include "sim/truth_calibration.h"

namespace ws {
namespace {

constexpr double kDeg = CV_PI / 180;
// Board poses: the largest angle between the board's normal and the line of
// sight to its centre, in either camera (more oblique boards are hard to
// detect), and how far the board turns from parallel to the image plane
// towards facing the aimed camera before its random tilt (further for an
// angle model, whose boards reach beyond 90 degrees off axis).
constexpr double kMaxViewAngleDeg = 60;
constexpr double kFaceFraction = 0.35, kFaceFractionAngle = 0.7;

// Uniform numbers from a seeded 64-bit generator, the same on every platform
// (std::uniform_real_distribution is not specified exactly).
class Random {
 public:
  explicit Random(uint64_t seed) : engine_(seed) {}
  double Uniform() { return double(engine_() >> 11) * 0x1.0p-53; }
  double Uniform(double a, double b) { return a + (b - a) * Uniform(); }

 private:
  std::mt19937_64 engine_;
};

cv::Matx33d Rotation(const cv::Vec3d& rotation_vector) {
  cv::Matx33d R;
  cv::Rodrigues(rotation_vector, R);
  return R;
}

cv::Vec3d ToCv(const Eigen::Vector3d& v) { return {v[0], v[1], v[2]}; }

bool InImage(const CameraModel& m, const cv::Point2d& p, double margin) {
  return p.x >= margin && p.y >= margin && p.x <= m.image_width - 1 - margin && p.y <= m.image_height - 1 - margin;
}

// Projection that knows where the lens model ends: a point farther off axis
// than the largest angle the image sees (the image border's, or the lens's
// image circle) is outside the image, whatever the model (extrapolated,
// perhaps folding back) says.
class Projector {
 public:
  Projector(const Camera& camera, double max_theta) : camera_(camera), theta_limit_(0) {
    const CameraModel& m = camera.model();
    for (int i = 0; i <= 64; ++i) {
      const double a = i / 64.0;
      for (const cv::Point2d p : {cv::Point2d(a * (m.image_width - 1), 0), cv::Point2d(a * (m.image_width - 1), m.image_height - 1),
                                  cv::Point2d(0, a * (m.image_height - 1)), cv::Point2d(m.image_width - 1, a * (m.image_height - 1))}) {
        const auto ray = camera.Unproject(Eigen::Vector2d(p.x, p.y));
        if (ray) theta_limit_ = std::max(theta_limit_, OffAxis(ToCv(*ray)));
      }
    }
    theta_limit_ = std::min(theta_limit_, max_theta);
    // The part of the image inside the image circle.
    box_ = cv::Rect2d(0, 0, m.image_width - 1, m.image_height - 1);
    if (max_theta < M_PI) {
      cv::Point2d low(m.cx, m.cy), high = low;
      for (const Eigen::Vector3d& ray : RaysAround(max_theta, 64)) {
        if (const auto p = camera.Project(ray)) {
          low = cv::Point2d(std::min(low.x, (*p)[0]), std::min(low.y, (*p)[1]));
          high = cv::Point2d(std::max(high.x, (*p)[0]), std::max(high.y, (*p)[1]));
        }
      }
      box_ &= cv::Rect2d(low, high);
    }
  }
  const Camera& camera() const { return camera_; }
  const CameraModel& model() const { return camera_.model(); }
  // The part of the image the lens sees: the image, or its image circle's bounding box in it.
  const cv::Rect2d& box() const { return box_; }

  // The pixel of X: false when the model has none (a pinhole: X behind the
  // camera). Beyond the image's largest angle (*beyond) the pixel of the
  // model without distortion stands in for it.
  bool operator()(const cv::Vec3d& X, cv::Point2d* pixel, bool* beyond) const {
    const auto p = camera_.Project(Eigen::Vector3d(X[0], X[1], X[2]));
    if (!p) return false;
    *beyond = OffAxis(X) > theta_limit_ * (1 + 1e-9);
    *pixel = cv::Point2d((*p)[0], (*p)[1]);
    if (*beyond) {
      double ideal[2] = {0, 0};
      if (camera_.IsAngleModel())
        ws::Theta::Ideal(X.val, ideal);
      else
        TanTheta::Ideal(X.val, ideal);
      const CameraModel& m = camera_.model();
      *pixel = cv::Point2d(m.fx * ideal[0] + m.cx, m.fy * ideal[1] + m.cy);
    }
    return true;
  }
  // The model's pixel of X (NaN where it has none), and whether it is in the
  // image `margin` pixels inside.
  bool InImage(const cv::Vec3d& X, double margin, cv::Point2d* pixel) const {
    bool beyond = false;
    if (!(*this)(X, pixel, &beyond)) {
      *pixel = cv::Point2d(NAN, NAN);
      return false;
    }
    if (beyond) {
      const auto p = camera_.Project(Eigen::Vector3d(X[0], X[1], X[2]));
      *pixel = cv::Point2d((*p)[0], (*p)[1]);
      return false;
    }
    return ws::InImage(model(), *pixel, margin);
  }
  // The ray of a pixel the lens sees.
  std::optional<cv::Vec3d> Ray(const cv::Point2d& pixel) const {
    const auto ray = camera_.Unproject(Eigen::Vector2d(pixel.x, pixel.y));
    if (!ray || OffAxis(ToCv(*ray)) > theta_limit_ * (1 + 1e-9)) return std::nullopt;
    return ToCv(*ray);
  }

 private:
  static double OffAxis(const cv::Vec3d& X) { return std::atan2(std::hypot(X[0], X[1]), X[2]); }

  const Camera& camera_;
  double theta_limit_;
  cv::Rect2d box_;
};

// Points along the outline of the board's squares grown by `grow` squares on
// every side, in the board frame (board_spec.h).
std::vector<cv::Vec3d> Outline(const BoardSpec& board, double grow) {
  const double s = board.square;
  const double x0 = -(1 + grow) * s, x1 = (board.cols + grow) * s;
  const double y0 = -(1 + grow) * s, y1 = (board.rows + grow) * s;
  std::vector<cv::Vec3d> points;
  const int per_side = 16 * (std::max(board.cols, board.rows) + 3);
  for (int k = 0; k < per_side; ++k) {
    const double a = double(k) / per_side;
    points.push_back({x0 + a * (x1 - x0), y0, 0});
    points.push_back({x1, y0 + a * (y1 - y0), 0});
    points.push_back({x1 - a * (x1 - x0), y1, 0});
    points.push_back({x0, y1 - a * (y1 - y0), 0});
  }
  return points;
}

// How far the projected outline reaches past each side of the image (less
// `margin`), pixels; negative: room to spare.
struct Overflow {
  bool projects = true;
  double left = -1e9, right = -1e9, top = -1e9, bottom = -1e9;
  bool fits() const { return projects && left <= 0 && right <= 0 && top <= 0 && bottom <= 0; }
};

Overflow OutlineOverflow(const Projector& project, const cv::Matx33d& R, const cv::Vec3d& t,
                         const std::vector<cv::Vec3d>& outline, double margin) {
  const CameraModel& m = project.model();
  Overflow o;
  for (const auto& q : outline) {
    cv::Point2d p;
    bool beyond = false;
    if (!project(R * q + t, &p, &beyond)) return Overflow{false};
    if (beyond && InImage(m, p, margin)) {  // outside, but the pinhole does not say where
      o.left = std::max(o.left, 1.0);
      continue;
    }
    o.left = std::max(o.left, margin - p.x);
    o.right = std::max(o.right, p.x - (m.image_width - 1 - margin));
    o.top = std::max(o.top, margin - p.y);
    o.bottom = std::max(o.bottom, p.y - (m.image_height - 1 - margin));
  }
  return o;
}

bool Facing(const cv::Matx33d& R, const cv::Vec3d& t) {
  return cv::Vec3d(R(0, 2), R(1, 2), R(2, 2)).dot(t) > 0;  // the board's z axis points away from the camera
}

// Does the board (R, t in the camera) face the camera, with all outline
// points in its image `margin` pixels inside?
bool BoardInside(const Projector& project, const cv::Matx33d& R, const cv::Vec3d& t,
                 const std::vector<cv::Vec3d>& outline, double margin) {
  return Facing(R, t) && OutlineOverflow(project, R, t, outline, margin).fits();
}

std::vector<SimFrame> PlanBoardFrames(const SimConfig& config, const Projector* projectors) {
  const SimBoardScene& scene = *config.board;
  const BoardSpec& board = scene.board;
  const std::vector<cv::Vec3d> keep_in = Outline(board, 1.0);
  const cv::Vec3d centre((board.cols - 1) * board.square / 2, (board.rows - 1) * board.square / 2, 0);
  Random random(MixSeed({config.seed, 0xb0a2d}));
  const int cells = scene.grid_cols * scene.grid_rows;
  std::vector<SimFrame> frames;
  for (int k = 0; k < scene.poses; ++k) {
    const bool both = scene.targets == SimBoardScene::Targets::both;
    const int cam = both ? k % 2 : scene.targets == SimBoardScene::Targets::left ? 0 : 1;
    const int step = both ? k / 2 : k;
    const int cell = step % cells, round = step / cells;
    const int gy = cell / scene.grid_cols;
    int gx = cell % scene.grid_cols;
    if (gy % 2 == 1) gx = scene.grid_cols - 1 - gx;  // serpentine: the board moves to a neighbour
    const Projector& project = projectors[cam];
    const CameraModel& m = project.model();
    const bool angle = project.camera().IsAngleModel();
    // Target position: the grid, jittered by up to a quarter cell (more on later rounds).
    const double jitter = round == 0 ? 0.25 : 0.5;
    auto fraction = [&](int g, int n) {
      if (n == 1) return std::clamp(0.5 + random.Uniform(-jitter, jitter) * 0.5, 0.0, 1.0);
      return std::clamp((g + random.Uniform(-jitter, jitter)) / (n - 1), 0.0, 1.0);
    };
    const double fx = fraction(gx, scene.grid_cols), fy = fraction(gy, scene.grid_rows);
    const cv::Rect2d& box = project.box();
    cv::Point2d target(box.x + fx * box.width, box.y + fy * box.height);
    double depth = random.Uniform(scene.depth_min, scene.depth_max);
    double tilt = random.Uniform(0, scene.max_tilt_deg) * kDeg;
    const double tilt_direction = random.Uniform(0, 2 * CV_PI);
    const double roll = random.Uniform(-scene.max_roll_deg, scene.max_roll_deg) * kDeg;
    const cv::Point2d principal(m.cx, m.cy);

    // The board at `target`, tilted, at `depth`: is it placed well?
    cv::Matx33d R;
    cv::Vec3d t;
    auto pose_at = [&](const cv::Point2d& at) {
      const auto ray = project.Ray(at);
      if (!ray) return false;
      const cv::Vec3d direction = *ray;
      const cv::Vec3d axis = cv::Vec3d(0, 0, 1).cross(direction);
      const double off_axis = std::atan2(cv::norm(axis), direction[2]);
      const double face_fraction = angle ? kFaceFractionAngle : kFaceFraction;
      const cv::Matx33d face = cv::norm(axis) > 1e-12
                                   ? Rotation(axis / cv::norm(axis) * (off_axis * face_fraction))
                                   : cv::Matx33d::eye();
      R = face * Rotation(cv::Vec3d(std::cos(tilt_direction), std::sin(tilt_direction), 0) * tilt) *
          Rotation(cv::Vec3d(0, 0, roll));
      t = direction * (angle ? depth : depth / direction[2]) - R * centre;
      // The line of sight from either camera to the board's centre.
      const cv::Vec3d normal(R(0, 2), R(1, 2), R(2, 2));
      const cv::Vec3d c = R * centre + t;
      const cv::Vec3d other_c = cam == 0 ? config.R * c + config.T : config.R.t() * (c - config.T);
      const cv::Vec3d other_normal = cam == 0 ? config.R * normal : config.R.t() * normal;
      const double min_cos = std::cos(kMaxViewAngleDeg * kDeg);
      return normal.dot(c) >= min_cos * cv::norm(c) && other_normal.dot(other_c) >= min_cos * cv::norm(other_c);
    };
    auto fits = [&](const cv::Point2d& at) {
      return pose_at(at) && BoardInside(project, R, t, keep_in, scene.edge_margin_px);
    };
    // Too oblique a view of the board (or from behind) along the line of
    // sight to the target: less tilt.
    for (int i = 0; i < 40 && !pose_at(target); ++i) tilt *= 0.8;
    // Where the board cannot fit even at the image centre, push it back.
    while (!fits(principal) && depth < scene.depth_max) depth = std::min(scene.depth_max, depth * 1.05);
    const bool placed = fits(principal);
    if (placed && !fits(target)) {
      // Bisect towards the target from the centre, then along x and along y
      // alone: the board ends up touching the image border(s) nearest the
      // target (board outlines grow monotonically enough towards the border).
      auto bisect = [&](cv::Point2d inside, cv::Point2d outside) {
        for (int i = 0; i < 24; ++i) {
          const cv::Point2d mid = 0.5 * (inside + outside);
          (fits(mid) ? inside : outside) = mid;
        }
        return inside;
      };
      const cv::Point2d goal = target;
      target = bisect(principal, goal);
      if (fits(cv::Point2d(goal.x, target.y))) target.x = goal.x;
      else target = bisect(target, cv::Point2d(goal.x, target.y));
      if (fits(cv::Point2d(target.x, goal.y))) target.y = goal.y;
      else target = bisect(target, cv::Point2d(target.x, goal.y));
    }
    if (placed) fits(target);  // leaves R, t of the final pose
    if (!placed)
      throw SimConfigError(config.source + ": scene.board: the board " + board.id +
                           " (with its white margin) does not fit inside the image, or is seen more obliquely than " +
                           std::to_string(int(kMaxViewAngleDeg)) + " degrees by a camera, even at depth " +
                           std::to_string(scene.depth_max) + " m: use a smaller board or a larger depth");
    SimFrame frame;
    frame.kind = SimFrame::Kind::board;
    frame.target_camera = cam;
    if (cam == 0) {
      frame.R = R;
      frame.t = t;
    } else {  // X_right = R X_left + T
      frame.R = config.R.t() * R;
      frame.t = config.R.t() * (t - config.T);
    }
    frames.push_back(frame);
  }
  return frames;
}

// The six faces of an axis-aligned box (centre, size) as planes
// X = R (u, v, 0) + t whose z axis points out of the box.
std::vector<SimFrame> BoxFaces(const cv::Vec3d& centre, const cv::Vec3d& size) {
  std::vector<SimFrame> faces;
  for (int axis = 0; axis < 3; ++axis)
    for (const double side : {1.0, -1.0}) {
      cv::Vec3d normal(0, 0, 0), along(0, 0, 0);
      normal[axis] = side;
      along[(axis + 1) % 3] = 1;
      const cv::Vec3d across = normal.cross(along);
      SimFrame face;
      face.kind = SimFrame::Kind::room;
      face.R = cv::Matx33d(along[0], across[0], normal[0], along[1], across[1], normal[1], along[2], across[2],
                           normal[2]);
      face.t = centre + normal * (size[axis] / 2);
      faces.push_back(face);
    }
  return faces;
}

// A plane X = R (u, v, 0) + t of the left camera's frame in camera `index`
// (X_right = R_rig X + T_rig).
void InCamera(const SimFrame& plane, int index, const SimConfig& config, cv::Matx33d* R, cv::Vec3d* t) {
  *R = index == 0 ? plane.R : config.R * plane.R;
  *t = index == 0 ? plane.t : config.R * plane.t + config.T;
}

// The plane-to-camera homography [r1 r2 t].
cv::Matx33d Homography(const cv::Matx33d& R, const cv::Vec3d& t) {
  return {R(0, 0), R(0, 1), t[0], R(1, 0), R(1, 1), t[1], R(2, 0), R(2, 1), t[2]};
}


}  // namespace

Simulator::Simulator(SimConfig config)
    : config_(std::move(config)),
      left_(config_.left),
      right_(config_.right),
      left_rays_(RayMap::For(config_.left, config_.max_theta[0])),
      right_rays_(RayMap::For(config_.right, config_.max_theta[1])) {
  const Projector projectors[2] = {Projector(left_, config_.max_theta[0]), Projector(right_, config_.max_theta[1])};
  if (config_.board) {
    frames_ = PlanBoardFrames(config_, projectors);
    board_front_ = std::make_unique<BoardPattern>(config_.board->board, config_.rendering, true);
    board_back_ = std::make_unique<BoardPattern>(config_.board->board, config_.rendering, false);
  }
  if (config_.wall) {
    const SimWallScene& wall = *config_.wall;
    SimFrame frame;
    frame.kind = SimFrame::Kind::wall;
    frame.R = Rotation(cv::Vec3d(0, wall.tilt_y_deg * kDeg, 0)) * Rotation(cv::Vec3d(wall.tilt_x_deg * kDeg, 0, 0));
    frame.t = cv::Vec3d(0, 0, wall.distance);
    for (int i = 0; i < wall.frames; ++i) frames_.push_back(frame);
    wall_ = std::make_unique<DotWallPattern>(wall.dot_size, wall.density, MixSeed({config_.seed, 0xd07}),
                                             config_.rendering);
  }
  if (config_.room) {
    const SimRoomScene& room = *config_.room;
    room_faces_ = BoxFaces(room.centre, room.size);
    for (size_t k = 0; k < room_faces_.size(); ++k)
      room_patterns_.push_back(std::make_unique<DotWallPattern>(
          room.dot_size, room.density, MixSeed({config_.seed, 0x2003, k}), config_.rendering));
    SimFrame frame;
    frame.kind = SimFrame::Kind::room;
    frame.t = room.centre;
    for (int i = 0; i < room.frames; ++i) frames_.push_back(frame);
  }
}


void Simulator::PlaneInCamera(int frame, int index, cv::Matx33d* R, cv::Vec3d* t) const {
  InCamera(frames_.at(size_t(frame)), index, config_, R, t);
}

cv::Mat Simulator::RenderLinear(int frame, int index) const {
  if (frames_.at(size_t(frame)).kind == SimFrame::Kind::room) {
    std::vector<cv::Matx33d> faces;
    std::vector<const DotWallPattern*> patterns;
    for (size_t k = 0; k < room_faces_.size(); ++k) {
      cv::Matx33d R;
      cv::Vec3d t;
      InCamera(room_faces_[k], index, config_, &R, &t);
      faces.push_back(Homography(R, t));
      patterns.push_back(room_patterns_[k].get());
    }
    return RenderRoom(rays(index), faces, patterns, config_.rendering.supersample);
  }
  cv::Matx33d R;
  cv::Vec3d t;
  PlaneInCamera(frame, index, &R, &t);
  const cv::Matx33d H = Homography(R, t);
  const PlanePattern* pattern = nullptr;
  if (frames_[frame].kind == SimFrame::Kind::wall) {
    pattern = wall_.get();
  } else {
    pattern = Facing(R, t) ? board_front_.get() : board_back_.get();
  }
  return RenderPlane(rays(index), H, *pattern, config_.rendering.supersample);
}

cv::Mat Simulator::RenderView(int frame, int index) const {
  return FinishImage(RenderLinear(frame, index), config_.rendering,
                     MixSeed({config_.seed, uint64_t(frame), uint64_t(index), 0x9015e}));
}

std::pair<cv::Mat, cv::Mat> Simulator::Render(int frame) const {
  return {RenderView(frame, 0), RenderView(frame, 1)};
}

SimViewTruth Simulator::ViewTruth(int frame, int index) const {
  const BoardSpec& board = config_.board->board;
  const Projector project(camera(index), config_.max_theta[size_t(index)]);
  cv::Matx33d R;
  cv::Vec3d t;
  PlaneInCamera(frame, index, &R, &t);
  const bool front = Facing(R, t);
  SimViewTruth view;
  int inside = 0;
  for (int id = 0; id < board.corner_count(); ++id) {
    const cv::Point3d q = board.ObjectPoint(id);
    cv::Point2d pixel;
    const bool in = project.InImage(R * cv::Vec3d(q.x, q.y, q.z) + t, 0, &pixel) && front;
    view.corners.push_back(pixel);
    view.in_image.push_back(in);
    inside += in;
  }
  if (inside == board.corner_count() && BoardInside(project, R, t, Outline(board, 1.0), 0))
    view.view = BoardView::full;
  else
    view.view = inside > 0 ? BoardView::partial : BoardView::none;
  return view;
}

SimFrameTruth Simulator::FrameTruth(int frame) const {
  const SimFrame& f = frames_.at(size_t(frame));
  SimFrameTruth truth;
  truth.index = frame;
  truth.R = f.R;
  truth.t = f.t;
  if (f.kind == SimFrame::Kind::board) {
    truth.kind = "board";
    truth.target = f.target_camera == 0 ? "left" : "right";
    truth.left = ViewTruth(frame, 0);
    truth.right = ViewTruth(frame, 1);
  } else if (f.kind == SimFrame::Kind::room) {
    truth.kind = "room";
    for (const SimFrame& face : room_faces_) {
      const cv::Vec3d normal(face.R(0, 2), face.R(1, 2), face.R(2, 2));
      truth.room_planes.emplace_back(normal[0], normal[1], normal[2], normal.dot(face.t));
    }
  } else {
    truth.kind = "wall";
    truth.wall_distance = config_.wall->distance;
    truth.wall_normal = cv::Vec3d(f.R(0, 2), f.R(1, 2), f.R(2, 2));
    truth.wall_offset = truth.wall_normal.dot(f.t);
  }
  return truth;
}

SimTruth Simulator::Truth() const {
  SimTruth truth;
  truth.config = config_.source;
  truth.seed = config_.seed;
  truth.rig = TrueStereoRig(config_);
  truth.max_theta = config_.max_theta;
  truth.board = config_.board ? config_.board->board.id : "";
  truth.rendering = config_.rendering;
  for (int i = 0; i < frame_count(); ++i) truth.frames.push_back(FrameTruth(i));
  return truth;
}

}  // namespace ws
