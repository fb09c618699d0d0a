// The simulator through a 200-degree angle-model rig (config/sim/fisheye.yaml):
// rays beyond 90 degrees, black past the image circle, board poses all around
// it, and detected corners where the true model projects them, beyond 90
// degrees too.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include <opencv2/core/utility.hpp>

#include "detect/corner_detector.h"
#include "models/fisheye_lens.h"
#include "sim/simulator.h"
#include "test_support.h"

namespace {

using namespace ws;
using namespace ws::test;

const Simulator& FisheyeSimulator() {
  static const Simulator simulator(LoadSimConfig(SourceDir() + "/config/sim/fisheye.yaml"));
  return simulator;
}

double OffAxisDeg(const cv::Vec3d& X) { return std::atan2(std::hypot(X[0], X[1]), X[2]) * 180 / M_PI; }

TEST(SimFisheye, ConfigDescribesTheKneeLensRig) {
  const SimConfig& config = FisheyeSimulator().config();
  EXPECT_EQ(config.left.distortion.kind, ModelKind::kBsplineTheta);
  EXPECT_EQ(config.left.distortion.coeffs, FisheyeKneeCamera().distortion.coeffs);
  EXPECT_EQ(config.right.fx, 297.5);
  EXPECT_NEAR(config.max_theta[0], 100 * M_PI / 180, 1e-12);
  EXPECT_NEAR(cv::norm(config.T), 0.15, 1e-12);
  const std::string dir = TempDir("sim-fisheye-config");
  // The truth file keeps the lens, its image circle and the corners past it.
  WriteSimTruth(dir + "/truth.yaml", FisheyeSimulator().Truth());
  const SimTruth truth = LoadSimTruth(dir + "/truth.yaml");
  EXPECT_EQ(truth.rig.left.distortion.coeffs, config.left.distortion.coeffs);
  EXPECT_NEAR(truth.max_theta[1], config.max_theta[1], 1e-12);
  const auto error = [&](const std::string& camera) {
    std::ofstream(dir + "/x.yaml") << "rig: {baseline: 0.15, left: " << camera << "}\nscene: {wall: {frames: 1}}\n";
    try {
      LoadSimConfig(dir + "/x.yaml");
    } catch (const SimConfigError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error("{lens: fisheye-knee, focal_length_mm: 1.3}").find("rig.left.focal_length_mm: the fisheye-knee lens has its own"),
            std::string::npos);
  EXPECT_NE(error("{lens: theia, field_deg: 190}").find("rig.left.field_deg: must be"), std::string::npos);
  EXPECT_NE(error("{lens: theia, field_deg: 180}").find("rig.left.field_deg: a pinhole model (bspline) sees less than 180"),
            std::string::npos);
}

TEST(SimFisheye, RaysReachBeyond90DegreesAndStopAtTheImageCircle) {
  const Simulator& simulator = FisheyeSimulator();
  for (int c = 0; c < 2; ++c) {
    const Camera& camera = simulator.camera(c);
    const RayMap& rays = simulator.rays(c);
    const double max_theta_deg = simulator.config().max_theta[c] * 180 / M_PI;
    double worst_vertex = 0, widest = 0;
    int inside = 0;
    for (int j = 0; j < rays.vertex_rows(); j += 3)
      for (int i = 0; i < rays.vertex_cols(); i += 3) {
        const auto exact = camera.Unproject(Eigen::Vector2d(i - 0.5, j - 0.5));
        const bool seen = exact && OffAxisDeg({(*exact)[0], (*exact)[1], (*exact)[2]}) <= max_theta_deg;
        ASSERT_EQ(rays.Valid(i, j), seen) << "vertex " << i << ", " << j;
        if (!seen) continue;
        const cv::Vec3d mapped = rays.Ray(i, j);
        worst_vertex = std::max(worst_vertex, cv::norm(mapped - cv::Vec3d((*exact)[0], (*exact)[1], (*exact)[2])));
        widest = std::max(widest, OffAxisDeg(mapped));
        ++inside;
      }
    const double interpolation_px = rays.MaxInterpolationErrorPx(camera, 160);
    std::printf("[ fisheye ] camera %d: rays to %.2f deg, vertex rays within %.1e px, interpolated within %.1e px\n", c,
                widest, worst_vertex * camera.model().fx, interpolation_px);
    EXPECT_GT(widest, 99.5);
    EXPECT_LT(worst_vertex * camera.model().fx, 1e-4);
    EXPECT_LT(interpolation_px, 2e-3);
    // The image circle (radius ~455 px) inside the 1280 x 960 image: about half of it.
    EXPECT_NEAR(inside / double((rays.vertex_rows() / 3 + 1) * (rays.vertex_cols() / 3 + 1)), 0.53, 0.05);
  }
  // Past the circle the image is black (noise clipped at 0), never the scene.
  const cv::Mat image = simulator.RenderView(0, 0);
  EXPECT_LT(cv::mean(image(cv::Rect(0, 0, 120, 90)))[0], 1.0);
  EXPECT_LT(cv::mean(image(cv::Rect(1160, 870, 120, 90)))[0], 1.0);
}

// Every aimed view: the target camera sees the whole board, the poses reach
// the circle all around, and the default detector's corners are where the
// true model projects them, beyond 90 degrees off axis too.
TEST(SimFisheye, DetectedCornersAreWhereTheModelProjectsThemBeyond90Degrees) {
  const Simulator& simulator = FisheyeSimulator();
  const SimTruth truth = simulator.Truth();
  const BoardSpec board = simulator.config().board->board;
  struct View {
    int frame, camera;
  };
  std::vector<View> views;
  int quadrants[2][4] = {};
  for (const auto& f : truth.frames) {
    if (f.kind != "board") continue;
    const int c = f.target == "left" ? 0 : 1;
    EXPECT_EQ((c == 0 ? f.left : f.right).view, BoardView::full) << "frame " << f.index;
    views.push_back({f.index, c});
  }
  struct Result {
    bool found = false;
    double sum_squares = 0, worst = 0, sum_squares_beyond = 0, widest = 0, widest_found = 0;
    int corners = 0, beyond = 0;
  };
  std::vector<Result> results(views.size());
  cv::parallel_for_(cv::Range(0, int(views.size())), [&](const cv::Range& range) {
    for (int v = range.start; v < range.end; ++v) {
      const View view = views[v];
      const cv::Mat image = simulator.RenderView(view.frame, view.camera);
      const SimViewTruth& vt = view.camera == 0 ? truth.frames[view.frame].left : truth.frames[view.frame].right;
      cv::Matx33d R;
      cv::Vec3d t;
      simulator.PlaneInCamera(view.frame, view.camera, &R, &t);
      std::vector<double> theta;
      Result& r = results[size_t(v)];
      for (int id = 0; id < board.corner_count(); ++id) {
        const cv::Point3d q = board.ObjectPoint(id);
        theta.push_back(OffAxisDeg(R * cv::Vec3d(q.x, q.y, q.z) + t));
        r.widest = std::max(r.widest, theta.back());
      }
      const BoardCorners found = MakeCornerDetector(board, kDefaultChessboardMethod)->Detect(image);
      r.found = found.ids.size() == size_t(board.corner_count());
      for (size_t k = 0; k < found.ids.size(); ++k) {
        const size_t id = size_t(found.ids[k]);
        const cv::Point2d error = cv::Point2d(found.points[k]) - vt.corners[id];
        r.sum_squares += error.dot(error);
        r.worst = std::max(r.worst, std::sqrt(error.dot(error)));
        ++r.corners;
        r.widest_found = std::max(r.widest_found, theta[id]);
        if (theta[id] > 90) {
          r.sum_squares_beyond += error.dot(error);
          ++r.beyond;
        }
      }
    }
  });
  double sum = 0, sum_beyond = 0, worst = 0, widest = 0;
  int corners = 0, beyond = 0, found = 0;
  for (size_t v = 0; v < views.size(); ++v) {
    const Result& r = results[v];
    sum += r.sum_squares;
    sum_beyond += r.sum_squares_beyond;
    corners += r.corners;
    beyond += r.beyond;
    found += r.found;
    worst = std::max(worst, r.worst);
    widest = std::max(widest, r.widest_found);
    if (!r.found) std::printf("[ fisheye ] missed frame %d camera %d (board to %.1f deg)\n", views[v].frame,
                              views[v].camera, r.widest);
    // Which quadrant of the circle the board's centre is in.
    const SimViewTruth& vt = views[v].camera == 0 ? truth.frames[views[v].frame].left : truth.frames[views[v].frame].right;
    const cv::Point2d centre = 0.5 * (vt.corners.front() + vt.corners.back());
    const CameraModel& m = simulator.camera(views[v].camera).model();
    ++quadrants[views[v].camera][(centre.x > m.cx) + 2 * (centre.y > m.cy)];
  }
  const double rms = std::sqrt(sum / std::max(1, corners)), rms_beyond = std::sqrt(sum_beyond / std::max(1, beyond));
  std::printf("[ fisheye ] %s found the board in %d of %zu aimed views; %d corners, error vs truth RMS %.4f px, max "
              "%.4f px; %d corners beyond 90 deg (to %.1f deg), RMS %.4f px\n",
              ChessboardMethodName(kDefaultChessboardMethod), found, views.size(), corners, rms, worst, beyond, widest,
              rms_beyond);
  for (int c = 0; c < 2; ++c)
    for (int q = 0; q < 4; ++q) EXPECT_GE(quadrants[c][q], 3) << "camera " << c << " quadrant " << q;
  // Boards reaching past 95 degrees are squeezed hard against the circle:
  // the detector misses a few of them, and finds the rest.
  EXPECT_GE(found, int(views.size()) * 9 / 10);
  EXPECT_GE(beyond, 50);
  EXPECT_GT(widest, 92);
  // Fisheye squares are curved: the corner refinement, which fits straight
  // edges around each corner, is less exact than on the Theia-like lens (0.05 px).
  EXPECT_LT(rms, 0.08);
  EXPECT_LT(rms_beyond, 0.08);
}

}  // namespace

namespace {

// The box room: its six faces in the truth file, and every pixel of the
// image circle textured (a ray always meets a face), where the wall frame
// leaves the rays past 90 degrees on the background.
TEST(SimFisheye, EveryRayInTheRoomMeetsATexturedFace) {
  const Simulator& simulator = FisheyeSimulator();
  const int room = simulator.frame_count() - 1, wall = room - 1;
  ASSERT_EQ(simulator.frames()[size_t(room)].kind, SimFrame::Kind::room);
  ASSERT_EQ(simulator.frames()[size_t(wall)].kind, SimFrame::Kind::wall);
  const std::string dir = TempDir("sim-fisheye-room");
  WriteSimTruth(dir + "/truth.yaml", simulator.Truth());
  const SimFrameTruth truth = LoadSimTruth(dir + "/truth.yaml").frames[size_t(room)];
  ASSERT_EQ(truth.kind, "room");
  ASSERT_EQ(truth.room_planes.size(), 6u);
  const SimRoomScene& scene = *simulator.config().room;
  for (int axis = 0; axis < 3; ++axis) {
    // Face 2 axis looks along +axis, 2 axis + 1 along -axis; distances from the left camera.
    EXPECT_NEAR(truth.room_planes[size_t(2 * axis)][axis], 1, 1e-12);
    EXPECT_NEAR(truth.room_planes[size_t(2 * axis)][3], scene.centre[axis] + scene.size[axis] / 2, 1e-9);
    EXPECT_NEAR(truth.room_planes[size_t(2 * axis + 1)][3], scene.size[axis] / 2 - scene.centre[axis], 1e-9);
  }
  const float background = float(simulator.config().rendering.background);
  for (int camera = 0; camera < 2; ++camera) {
    const cv::Mat room_image = simulator.RenderLinear(room, camera), wall_image = simulator.RenderLinear(wall, camera);
    const cv::Mat circle = room_image > 0;  // past the image circle: black
    const double missed_room = cv::countNonZero(room_image == background) / double(cv::countNonZero(circle));
    const double missed_wall = cv::countNonZero(wall_image == background) / double(cv::countNonZero(circle));
    std::printf("[ room ] camera %d: background in %.4f of the image circle (the wall frame: %.3f)\n", camera,
                missed_room, missed_wall);
    EXPECT_LT(missed_room, 0.001);
    EXPECT_GT(missed_wall, 0.05);
  }
}

}  // namespace
