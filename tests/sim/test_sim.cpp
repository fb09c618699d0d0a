// The built-in simulator (common/sim): config checking, exact rendering
// (ray maps, corners where the lens model puts them), the wall's texture,
// the ground-truth file, and stereo-capture --source sim: end to end.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>

#include <opencv2/imgproc.hpp>

#include "detect/corner_detector.h"
#include "lcm_io/channels.h"
#include "lcm_io/image_codec.h"
#include "source/sim_source.h"
#include "sim/simulator.h"
#include "source/make_source.h"
#include "test_support.h"
#include "widestereo/stereo_frame_t.hpp"

namespace {

using namespace ws;
using namespace ws::test;

std::string ConfigPath(const std::string& name) { return SourceDir() + "/config/sim/" + name; }

// The default config's simulator, built once for the tests that share it.
const Simulator& DefaultSimulator() {
  static const Simulator simulator(LoadSimConfig(ConfigPath("default.yaml")));
  return simulator;
}

// A small scene at a quarter of the resolution (320 x 240, same field of view).
SimConfig SmallConfig(int poses = 3, int wall_frames = 1) {
  SimConfig config = DefaultSimConfig(0.25);
  config.board->poses = poses;
  config.board->board = ParseBoardSpec("chessboard:9x6:0.05");
  config.board->depth_min = 0.6;
  config.board->depth_max = 1.0;
  config.wall->frames = wall_frames;
  return config;
}

// ---------------------------------------------------------------------------
// Config

TEST(SimConfig, DefaultFileDescribesTheRigAndScene) {
  const SimConfig config = LoadSimConfig(ConfigPath("default.yaml"));
  EXPECT_EQ(config.left.image_width, 1280);
  EXPECT_EQ(config.left.image_height, 960);
  EXPECT_NEAR(config.left.fx, 1.3 / 0.00375, 1e-9);
  EXPECT_EQ(config.left.cx, 640);
  EXPECT_EQ(config.left.distortion.kind, ModelKind::kBspline);
  EXPECT_EQ(config.right.distortion.coeffs, config.left.distortion.coeffs);
  // The table in the file and the one compiled into the library give one lens.
  EXPECT_EQ(config.left.distortion.coeffs, SimDefaultCamera().distortion.coeffs);
  EXPECT_LT(cv::norm(config.T - cv::Vec3d(-0.3, 0, 0)), 1e-12);
  EXPECT_LT(cv::norm(config.R - cv::Matx33d::eye()), 1e-12);
  ASSERT_TRUE(config.board);
  EXPECT_EQ(config.board->board.id, "chessboard:9x6:0.05");
  EXPECT_EQ(config.board->poses, 30);
  ASSERT_TRUE(config.wall);
  EXPECT_EQ(config.wall->distance, 2.0);
  EXPECT_EQ(DefaultSimulator().frame_count(), 35);
}

TEST(SimConfig, EveryShippedConfigLoads) {
  for (const std::string name : {"default.yaml", "wall.yaml", "poly6.yaml", "charuco.yaml", "fisheye.yaml"}) {
    SCOPED_TRACE(name);
    const SimConfig config = LoadSimConfig(ConfigPath(name));
    EXPECT_NO_THROW(Simulator{config});
  }
  const SimConfig poly6 = LoadSimConfig(ConfigPath("poly6.yaml"));
  EXPECT_EQ(poly6.left.distortion.kind, ModelKind::kPoly6);
  EXPECT_EQ(poly6.left.distortion.coeffs, (std::vector<double>{-0.06, 0.004, -0.0001}));
  EXPECT_EQ(poly6.left.fx, 450);
}

TEST(SimConfig, TableLensesCanBeFittedWithEveryModel) {
  const std::string dir = TempDir("sim-fit");
  for (const std::string fit : {"bspline", "poly6", "poly12"}) {
    SCOPED_TRACE(fit);
    std::ofstream(dir + "/" + fit + ".yaml")
        << "rig: {baseline: 0.3, left: {lens: 'table:" << SourceDir() << "/config/lenses/theia-my125m-like.csv', fit: "
        << fit << "}}\nscene: {wall: {frames: 1}}\n";
    const SimConfig config = LoadSimConfig(dir + "/" + fit + ".yaml");
    EXPECT_EQ(config.left.distortion.kind, ParseModelKind(fit));
    // Each fit follows the table closely: the image corner's ray agrees with the spline's within a few pixels.
    const Camera fitted(config.left), spline(SimDefaultCamera());
    const auto ray = spline.Unproject(Eigen::Vector2d(0, 0));
    const auto pixel = fitted.Project(*ray);
    ASSERT_TRUE(pixel);
    EXPECT_LT(pixel->norm(), fit == "bspline" ? 1e-9 : 5.0);
  }
}

TEST(SimConfig, BadConfigIsAClearErrorNamingFileAndField) {
  const std::string rig = "rig: {baseline: 0.3, left: {lens: theia, image_size: [320, 240]}}\n";
  const std::string scene = "scene: {wall: {frames: 1}}\n";
  struct Case {
    std::string yaml;
    std::vector<std::string> says;
  };
  const std::vector<Case> cases = {
      {"rig: [1, 2\n", {"not valid YAML"}},
      {scene, {"rig: is required"}},
      {rig, {"scene: is required"}},
      {rig + scene + "rendering: {supersample: 0}\n", {"rendering.supersample", "from 1 to 16", "not 0"}},
      {rig + scene + "rendering: {blur_sigma: wide}\n", {"rendering.blur_sigma", "must be a number", "'wide'"}},
      {rig + scene + "rendering: {black: 200, white: 100}\n", {"rendering.white", "greater than black"}},
      {rig + scene + "colour: red\n", {"colour: unknown field"}},
      {rig + "scene: {wall: {frames: 1, dot_szie: 0.01}}\n", {"scene.wall.dot_szie: unknown field", "dot_size"}},
      {rig + "scene: {}\n", {"scene: needs a board, a wall or a room"}},
      {rig + "scene: {room: {size: [4, 3, 4], centre: [0, 0, 2.5]}}\n", {"scene.room.centre", "both cameras must be inside"}},
      {rig + "scene: {board: {spec: chessboard:9x6}}\n", {"scene.board.spec", "chessboard takes 3"}},
      {rig + "scene: {board: {spec: chessboard:9x6:0.05, depth: [1.0, 0.5]}}\n", {"scene.board.depth", "MIN <= MAX"}},
      {rig + "scene: {board: {spec: chessboard:9x6:0.05, poses: 0}}\n", {"scene.board.poses", "from 1"}},
      {rig + "scene: {board: {spec: chessboard:9x6:0.5, depth: [0.5, 0.6]}}\n", {"scene.board", "does not fit"}},
      {"rig: {left: {lens: theia}}\n" + scene, {"rig.baseline: is required"}},
      {"rig: {baseline: -0.3, left: {lens: theia}}\n" + scene, {"rig.baseline", "greater than 0", "-0.3"}},
      {"rig: {baseline: 0.3, T: [-0.3, 0, 0], left: {lens: theia}}\n" + scene, {"rig.T", "either baseline or T"}},
      {"rig: {baseline: 0.3}\n" + scene, {"rig.left", "is required"}},
      {"rig: {baseline: 0.3, left: {lens: fisheye}}\n" + scene, {"rig.left.lens", "must be theia, fisheye-knee, table:PATH"}},
      {"rig: {baseline: 0.3, left: {lens: 'poly6:0.1,0.2'}}\n" + scene, {"rig.left.lens", "3 comma-separated"}},
      {"rig: {baseline: 0.3, left: {lens: 'poly6:0.1,x,0'}}\n" + scene, {"rig.left.lens", "'x' is not a number"}},
      {"rig: {baseline: 0.3, left: {lens: 'table:no/such.csv'}}\n" + scene, {"rig.left.lens", "no/such.csv"}},
      {"rig: {baseline: 0.3, left: {lens: theia, image_size: [320]}}\n" + scene, {"rig.left.image_size", "[WIDTH, HEIGHT]"}},
      {"rig: {baseline: 0.3, left: {lens: theia, fx: 0}}\n" + scene, {"rig.left.fx", "greater than 0"}},
      {"rig: {baseline: 0.3, left: {lens: 'poly6:-0.5,0,0'}}\n" + scene, {"rig.left.lens", "cannot be inverted"}},
      {"rig: {baseline: 0.3, left: {lens: theia}, right: {lens: theia, zoom: 2}}\n" + scene,
       {"rig.right.zoom: unknown field"}},
  };
  const std::string dir = TempDir("sim-bad-config");
  for (size_t i = 0; i < cases.size(); ++i) {
    const std::string path = dir + "/bad" + std::to_string(i) + ".yaml";
    std::ofstream(path) << cases[i].yaml;
    std::string message;
    try {
      Simulator simulator(LoadSimConfig(path));
      message = "(no error)";
    } catch (const SimConfigError& e) {
      message = e.what();
    }
    SCOPED_TRACE(cases[i].yaml + " -> " + message);
    EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << "the message starts with the file";
    for (const auto& part : cases[i].says) EXPECT_NE(message.find(part), std::string::npos) << part;
  }
  EXPECT_THROW(LoadSimConfig(dir + "/missing.yaml"), SimConfigError);
}

// ---------------------------------------------------------------------------
// Ray maps

TEST(RayMap, MatchesTheLensModelToFarBelowAHundredthOfAPixel) {
  const Simulator& simulator = DefaultSimulator();
  const Camera& camera = simulator.camera(0);
  const RayMap& rays = simulator.rays(0);
  EXPECT_EQ(rays.invalid_count(), 0);
  // Vertex rays against Camera::Unproject, in pixels (angle times focal length).
  double worst_vertex = 0;
  for (int j = 0; j < rays.vertex_rows(); j += 7)
    for (int i = 0; i < rays.vertex_cols(); i += 9) {
      const auto exact = camera.Unproject(Eigen::Vector2d(i - 0.5, j - 0.5));
      ASSERT_TRUE(exact);
      const cv::Vec3d mapped = rays.Ray(i, j);
      worst_vertex = std::max(worst_vertex, cv::norm(mapped - cv::Vec3d((*exact)[0], (*exact)[1], (*exact)[2])));
    }
  const double vertex_px = worst_vertex * camera.model().fx;
  // Inside pixels (bilinear between the vertices), through Project.
  const double interpolation_px = rays.MaxInterpolationErrorPx(camera, 160);
  std::printf("[ ray map ] 1280x960 Theia-like bspline: vertex rays within %.1e px, interpolated rays within %.1e px\n",
              vertex_px, interpolation_px);
  RecordProperty("vertex_error_px", std::to_string(vertex_px));
  RecordProperty("interpolation_error_px", std::to_string(interpolation_px));
  EXPECT_LT(vertex_px, 1e-4);
  EXPECT_LT(interpolation_px, 1e-3);

  // A lens with tangential terms takes the general path (Camera::Unproject per vertex).
  CameraModel tangential = SimDefaultCamera(0.25);
  tangential.p1 = 2e-3;
  tangential.p2 = -1e-3;
  const RayMap map(tangential);
  EXPECT_EQ(map.invalid_count(), 0);
  // (The interpolation error grows with the pixels' angular size: 4 x at a quarter of the resolution.)
  EXPECT_LT(map.MaxInterpolationErrorPx(Camera(tangential), 64), 4e-3);
}

// ---------------------------------------------------------------------------
// Rendering

TEST(SimRender, SameConfigAndSeedGiveTheSameImages) {
  const SimConfig config = SmallConfig();
  const Simulator a(config), b(config);
  ASSERT_EQ(a.frame_count(), 4);
  for (int frame = 0; frame < a.frame_count(); ++frame) {
    const auto [al, ar] = a.Render(frame);
    const auto [bl, br] = b.Render(frame);
    ASSERT_EQ(al.size(), cv::Size(320, 240));
    EXPECT_EQ(al.type(), CV_8UC1);
    EXPECT_EQ(cv::norm(al, bl, cv::NORM_INF), 0) << frame;
    EXPECT_EQ(cv::norm(ar, br, cv::NORM_INF), 0) << frame;
  }
  SimConfig other = config;
  other.seed = 2;
  const Simulator c(other);
  EXPECT_GT(cv::norm(c.RenderView(0, 0), a.RenderView(0, 0), cv::NORM_L1), 0);
  EXPECT_NE(cv::norm(c.frames()[0].t - a.frames()[0].t), 0) << "the seed moves the board";
}

TEST(SimRender, SupersamplingOnlyWhereNeededEqualsSupersamplingEverywhere) {
  // Region test: a pixel whose corners all hit one convex region of one grey
  // level is that level. Compare with brute force on a board frame and a wall frame.
  SimConfig config = SmallConfig(1, 1);
  config.board->board = ParseBoardSpec("charuco:9x6:0.05:0.037:DICT_5X5_100");
  const Simulator simulator(config);
  for (int frame = 0; frame < simulator.frame_count(); ++frame) {
    const RayMap& rays = simulator.rays(0);
    cv::Matx33d R;
    cv::Vec3d t;
    simulator.PlaneInCamera(frame, 0, &R, &t);
    const BoardPattern board(config.board->board, config.rendering);
    const DotWallPattern wall(config.wall->dot_size, config.wall->density, 1, config.rendering);
    const PlanePattern& pattern = simulator.frames()[frame].kind == SimFrame::Kind::wall
                                      ? static_cast<const PlanePattern&>(wall)
                                      : static_cast<const PlanePattern&>(board);
    const cv::Matx33d H(R(0, 0), R(0, 1), t[0], R(1, 0), R(1, 1), t[1], R(2, 0), R(2, 1), t[2]);
    const cv::Mat adaptive = RenderPlane(rays, H, pattern, 4);
    const cv::Matx33d M = H.inv();
    cv::Mat brute(adaptive.size(), CV_32FC1);
    for (int y = 0; y < brute.rows; ++y)
      for (int x = 0; x < brute.cols; ++x) {
        double sum = 0;
        for (int sy = 0; sy < 4; ++sy)
          for (int sx = 0; sx < 4; ++sx) {
            const cv::Vec3d p = M * *rays.Interpolate(x - 0.5 + (sx + 0.5) / 4, y - 0.5 + (sy + 0.5) / 4);
            sum += p[2] > 0 ? pattern.At(p[0] / p[2], p[1] / p[2]).value : pattern.Miss().value;
          }
        brute.at<float>(y, x) = float(sum / 16);
      }
    EXPECT_LT(cv::norm(adaptive, brute, cv::NORM_INF), 1e-3) << "frame " << frame;
  }
}

// Detected corners against the truth, over every full view of the default
// scene (30 board poses, 1280 x 960, default blur and noise). The detectors
// see the board's part of the image (its truth bounding box grown by two
// squares): the same pixels around every corner, a fraction of the time.
TEST(SimRender, DetectedCornersAreWhereTheModelProjectsThem) {
  const Simulator& simulator = DefaultSimulator();
  const SimTruth truth = simulator.Truth();
  const BoardSpec board = simulator.config().board->board;
  struct View {
    int frame, camera;
  };
  std::vector<View> views;
  for (const auto& f : truth.frames)
    if (f.kind == "board")
      for (int c = 0; c < 2; ++c)
        if ((c == 0 ? f.left : f.right).view == BoardView::full) views.push_back({f.index, c});
  ASSERT_GE(views.size(), 40u) << "most board poses are seen whole by both cameras";

  const ChessboardMethod methods[2] = {ChessboardMethod::sb, ChessboardMethod::classic};
  struct Result {
    bool found = false;
    double sum_squares = 0, worst = 0;
    int corners = 0;
  };
  std::vector<Result> results(views.size() * 2);
  const auto start = std::chrono::steady_clock::now();
  cv::parallel_for_(cv::Range(0, int(views.size())), [&](const cv::Range& range) {
    for (int v = range.start; v < range.end; ++v) {
      const View view = views[v];
      const cv::Mat image = simulator.RenderView(view.frame, view.camera);
      const SimViewTruth& vt = view.camera == 0 ? truth.frames[view.frame].left : truth.frames[view.frame].right;
      cv::Rect box = cv::boundingRect(std::vector<cv::Point2f>(vt.corners.begin(), vt.corners.end()));
      const int grow = int(2.5 * simulator.camera(view.camera).model().fx * board.square / 0.4);
      box = cv::Rect(box.x - grow, box.y - grow, box.width + 2 * grow, box.height + 2 * grow) &
            cv::Rect(0, 0, image.cols, image.rows);
      for (int m = 0; m < 2; ++m) {
        const BoardCorners found = MakeCornerDetector(board, methods[m])->Detect(image(box));
        Result& r = results[size_t(v) * 2 + m];
        r.found = found.ids.size() == size_t(board.corner_count());
        for (size_t k = 0; k < found.ids.size(); ++k) {
          const cv::Point2d error =
              cv::Point2d(found.points[k]) + cv::Point2d(box.tl()) - vt.corners[size_t(found.ids[k])];
          r.sum_squares += error.dot(error);
          r.worst = std::max(r.worst, std::sqrt(error.dot(error)));
          ++r.corners;
        }
      }
    }
  });
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  double rms[2] = {0, 0};
  for (int m = 0; m < 2; ++m) {
    double sum = 0, worst = 0;
    int corners = 0, found = 0;
    for (size_t v = 0; v < views.size(); ++v) {
      const Result& r = results[v * 2 + m];
      sum += r.sum_squares;
      corners += r.corners;
      found += r.found;
      worst = std::max(worst, r.worst);
    }
    rms[m] = std::sqrt(sum / std::max(1, corners));
    std::printf("[ corners ] %-7s found the board in %d of %zu full views; error vs truth RMS %.4f px, max %.4f px\n",
                ChessboardMethodName(methods[m]), found, views.size(), rms[m], worst);
    RecordProperty(std::string(ChessboardMethodName(methods[m])) + "_rms_px", std::to_string(rms[m]));
    RecordProperty(std::string(ChessboardMethodName(methods[m])) + "_found", std::to_string(found));
  }
  std::printf("[ corners ] rendering and detection of %zu views: %.1f s\n", views.size(), seconds);
  // Both detectors end at the corners' saddle points (corner_refinement.h):
  // measured 0.020 px RMS each (the classic one with cornerSubPix alone: 0.043 px).
  for (int m = 0; m < 2; ++m) EXPECT_LT(rms[m], 0.035) << ChessboardMethodName(methods[m]);
  for (size_t v = 0; v < views.size(); ++v)
    for (int m = 0; m < 2; ++m)
      if (!results[v * 2 + m].found) {
        std::printf("[ corners ] %s missed frame %d camera %d\n", ChessboardMethodName(methods[m]), views[v].frame,
                    views[v].camera);
        EXPECT_NE(methods[m], kDefaultChessboardMethod) << "the default detector missed a board";
      }
}

TEST(SimRender, WallHasTextureWhereverItIsSeen) {
  const Simulator& simulator = DefaultSimulator();
  const int wall = simulator.frame_count() - 1;
  ASSERT_EQ(simulator.frames()[wall].kind, SimFrame::Kind::wall);
  for (int c = 0; c < 2; ++c) {
    const cv::Mat image = simulator.RenderView(wall, c);
    // Every 33 x 33 window (the paper's block-matching window) has contrast.
    cv::Mat image32, mean, mean_sq;
    image.convertTo(image32, CV_32F);
    cv::blur(image32, mean, cv::Size(33, 33));
    cv::blur(image32.mul(image32), mean_sq, cv::Size(33, 33));
    cv::Mat deviation;
    cv::sqrt(cv::max(mean_sq - mean.mul(mean), 0), deviation);
    double least = 0;
    cv::minMaxLoc(deviation(cv::Rect(16, 16, image.cols - 32, image.rows - 32)), &least);
    EXPECT_GT(least, 40) << "camera " << c;
  }
  // The wall stands still: two wall frames differ by their noise only.
  const cv::Mat a = simulator.RenderLinear(wall, 0), b = simulator.RenderLinear(wall - 1, 0);
  EXPECT_EQ(cv::norm(a, b, cv::NORM_INF), 0);
  const SimFrameTruth t = simulator.FrameTruth(wall);
  EXPECT_EQ(t.kind, "wall");
  EXPECT_EQ(t.wall_distance, 2.0);
  EXPECT_LT(cv::norm(t.wall_normal - cv::Vec3d(0, 0, 1)), 1e-12);
  EXPECT_DOUBLE_EQ(t.wall_offset, 2.0);
}

TEST(SimRender, PosesReachThePeripheryOfBothImages) {
  const Simulator& simulator = DefaultSimulator();
  const SimTruth truth = simulator.Truth();
  for (int c = 0; c < 2; ++c) {
    // True corners of full views, binned on a 4 x 4 grid over the image: every bin has some.
    int bins[4][4] = {};
    double min_x = 1e9, max_x = -1e9, min_y = 1e9, max_y = -1e9;
    for (const auto& f : truth.frames) {
      if (f.kind != "board") continue;
      const SimViewTruth& v = c == 0 ? f.left : f.right;
      if ((c == 0 ? "left" : "right") == f.target) {
        EXPECT_EQ(v.view, BoardView::full) << "frame " << f.index;
      }
      if (v.view != BoardView::full) continue;
      for (const auto& p : v.corners) {
        ++bins[std::clamp(int(p.y / 240), 0, 3)][std::clamp(int(p.x / 320), 0, 3)];
        min_x = std::min(min_x, p.x);
        max_x = std::max(max_x, p.x);
        min_y = std::min(min_y, p.y);
        max_y = std::max(max_y, p.y);
      }
    }
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) EXPECT_GT(bins[i][j], 0) << "camera " << c << " bin " << i << "," << j;
    // The outermost corners are two squares (one square and the white margin) inside the board's edge.
    EXPECT_LT(min_x, 120);
    EXPECT_GT(max_x, 1279 - 120);
    EXPECT_LT(min_y, 120);
    EXPECT_GT(max_y, 959 - 120);
  }
}

// ChArUco boards running off the image: the detector finds the corners it
// sees, with their true ids (each within a third of the distance to the
// nearest other corner of where the truth puts it), close to the truth.
TEST(SimRender, ChArUcoCornersOfPartialViewsCarryTheirTrueIds) {
  SimConfig config = LoadSimConfig(ConfigPath("charuco.yaml"));
  config.board->poses = 6;
  const Simulator simulator(config);
  const auto detector = MakeCornerDetector(config.board->board);
  int partial_views_found = 0;
  double sum = 0;
  int corners = 0;
  for (int frame = 0; frame < simulator.frame_count(); ++frame) {
    const SimFrameTruth t = simulator.FrameTruth(frame);
    const int c = t.target == "left" ? 0 : 1;
    const SimViewTruth& v = c == 0 ? t.left : t.right;
    const BoardCorners found = detector->Detect(simulator.RenderView(frame, c));
    for (size_t k = 0; k < found.ids.size(); ++k) {
      const int id = found.ids[k];
      ASSERT_TRUE(v.in_image[id]) << "frame " << frame << " id " << id;
      double nearest = INFINITY;
      for (size_t other = 0; other < v.corners.size(); ++other)
        if (int(other) != id) nearest = std::min(nearest, cv::norm(v.corners[other] - v.corners[id]));
      const cv::Point2d error = cv::Point2d(found.points[k]) - v.corners[id];
      EXPECT_LT(std::hypot(error.x, error.y), nearest / 3) << "frame " << frame << " id " << id;
      sum += error.dot(error);
      ++corners;
    }
    if (v.view == BoardView::partial && !found.empty()) ++partial_views_found;
  }
  std::printf("[ charuco ] %d corners found with their true ids, RMS %.4f px; %d partial views found\n", corners,
              std::sqrt(sum / std::max(1, corners)), partial_views_found);
  EXPECT_GT(partial_views_found, 0);
  EXPECT_GT(corners, 100);
  EXPECT_LT(std::sqrt(sum / std::max(1, corners)), 0.2);
}

// ---------------------------------------------------------------------------
// Ground truth

TEST(SimTruth, FileRoundTrip) {
  const SimTruth truth = DefaultSimulator().Truth();
  const std::string path = TempDir("sim-truth") + "/truth.yaml";
  WriteSimTruth(path, truth);
  const SimTruth loaded = LoadSimTruth(path);
  EXPECT_EQ(loaded.config, truth.config);
  EXPECT_EQ(loaded.seed, truth.seed);
  for (const auto& [a, b] :
       {std::pair(&loaded.rig.left, &truth.rig.left), std::pair(&loaded.rig.right, &truth.rig.right)}) {
    EXPECT_EQ(a->distortion.kind, b->distortion.kind);
    EXPECT_EQ(a->distortion.degree, b->distortion.degree);
    EXPECT_EQ(a->distortion.knots, b->distortion.knots);
    EXPECT_EQ(a->distortion.coeffs, b->distortion.coeffs);
    EXPECT_EQ(a->Intrinsics(), b->Intrinsics());
    EXPECT_EQ(a->image_width, b->image_width);
    EXPECT_EQ(a->image_height, b->image_height);
  }
  EXPECT_EQ(loaded.rig.R, truth.rig.R);
  EXPECT_EQ(loaded.rig.T, truth.rig.T);
  EXPECT_EQ(loaded.board, truth.board);
  EXPECT_EQ(loaded.rendering.noise_sigma, truth.rendering.noise_sigma);
  ASSERT_EQ(loaded.frames.size(), truth.frames.size());
  for (size_t i = 0; i < truth.frames.size(); ++i) {
    const auto &a = loaded.frames[i], &b = truth.frames[i];
    EXPECT_EQ(a.index, b.index);
    EXPECT_EQ(a.kind, b.kind);
    EXPECT_EQ(cv::norm(a.R - b.R), 0);
    EXPECT_EQ(cv::norm(a.t - b.t), 0);
    EXPECT_EQ(a.target, b.target);
    for (const auto& [va, vb] : {std::pair(&a.left, &b.left), std::pair(&a.right, &b.right)}) {
      EXPECT_EQ(va->view, vb->view);
      EXPECT_EQ(va->in_image, vb->in_image);
      ASSERT_EQ(va->corners.size(), vb->corners.size());
      for (size_t k = 0; k < vb->corners.size(); ++k) EXPECT_EQ(va->corners[k], vb->corners[k]);
    }
    EXPECT_EQ(a.wall_distance, b.wall_distance);
    EXPECT_EQ(a.wall_offset, b.wall_offset);
  }
  // OpenCV users read K, R and T directly, as from a calibration file.
  cv::FileStorage fs(path, cv::FileStorage::READ);
  cv::Mat K, R;
  fs["cameras"][0]["camera_matrix"] >> K;
  fs["R"] >> R;
  EXPECT_EQ(K.at<double>(0, 0), truth.rig.left.fx);
  EXPECT_EQ(R.at<double>(1, 1), 1.0);
}

TEST(SimTruth, CornersAreTheModelsProjectionsOfTheBoardPose) {
  const Simulator& simulator = DefaultSimulator();
  const BoardSpec& board = simulator.config().board->board;
  const SimFrameTruth t = simulator.FrameTruth(4);
  for (int c = 0; c < 2; ++c) {
    cv::Matx33d R = t.R;
    cv::Vec3d x = t.t;
    if (c == 1) {
      R = simulator.config().R * t.R;
      x = simulator.config().R * t.t + simulator.config().T;
    }
    for (int id = 0; id < board.corner_count(); ++id) {
      const cv::Point3d q = board.ObjectPoint(id);
      const cv::Vec3d X = R * cv::Vec3d(q.x, q.y, q.z) + x;
      const auto p = simulator.camera(c).Project(Eigen::Vector3d(X[0], X[1], X[2]));
      ASSERT_TRUE(p);
      const cv::Point2d truth = (c == 0 ? t.left : t.right).corners[id];
      EXPECT_EQ(truth, cv::Point2d((*p)[0], (*p)[1]));
    }
  }
}

TEST(SimTruth, LoaderNamesTheBadField) {
  const std::string dir = TempDir("sim-truth-bad");
  WriteSimTruth(dir + "/good.yaml", DefaultSimulator().Truth());
  std::ifstream in(dir + "/good.yaml");
  std::stringstream text;
  text << in.rdbuf();
  std::string broken = text.str();
  broken.replace(broken.find("p1:"), 3, "pq:");
  std::ofstream(dir + "/bad.yaml") << broken;
  try {
    LoadSimTruth(dir + "/bad.yaml");
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("cameras[0].p1: missing"), std::string::npos) << e.what();
  }
  EXPECT_THROW(LoadSimTruth(dir + "/none.yaml"), std::runtime_error);
}

// ---------------------------------------------------------------------------
// Source and process

TEST(SimSource, FramesInOrderEndOrLoop) {
  auto simulator = std::make_shared<const Simulator>(SmallConfig(2, 1));
  SimSource once(simulator, false);
  std::vector<StereoPair> pairs;
  while (auto pair = once.Next()) pairs.push_back(*pair);
  ASSERT_EQ(pairs.size(), 3u);
  EXPECT_EQ(pairs[0].label, "sim frame 0/3 (board, aimed at left)");
  EXPECT_EQ(pairs[1].label, "sim frame 1/3 (board, aimed at right)");
  EXPECT_EQ(pairs[2].label, "sim frame 2/3 (wall)");
  EXPECT_EQ(once.Counters().begin()->second.received, 3);
  SimSource looping(simulator, true);
  for (int i = 0; i < 3; ++i) looping.Next();
  const auto again = looping.Next();
  ASSERT_TRUE(again);
  EXPECT_EQ(again->label, pairs[0].label);
  EXPECT_EQ(cv::norm(again->left, pairs[0].left, cv::NORM_INF), 0);
}

TEST(SimSource, SpecChoosesTheTruthFile) {
  const std::string dir = TempDir("sim-spec");
  const std::string config = dir + "/small.yaml";
  std::ofstream(config) << "rig: {baseline: 0.3, left: {lens: theia, image_size: [160, 120], pixel_pitch_mm: 0.03}}\n"
                           "scene: {wall: {frames: 2}}\n";
  auto source = MakeStereoSource("sim:" + config + "?truth=" + dir + "/t/truth.yaml", SourceOptions{});
  EXPECT_EQ(LoadSimTruth(dir + "/t/truth.yaml").frames.size(), 2u);
  EXPECT_EQ(DefaultSimTruthPath("config/sim/wall.yaml"), "logs/sim/wall.truth.yaml");
  EXPECT_THROW(MakeStereoSource("sim:" + config + "?thruth=x", SourceOptions{}), std::invalid_argument);
  EXPECT_THROW(MakeStereoSource("sim:" + dir + "/none.yaml?truth=x", SourceOptions{}), SimConfigError);
}

TEST(SimCapture, ProcessPublishesTheFramesItRenders) {
  const std::string dir = TempDir("sim-capture");
  const auto r = RunCommand({"stereo-capture", "--source", "sim:config/sim/default.yaml?truth=" + dir + "/truth.yaml",
                             "--count", "3", "--frame-clock", "--log-dir", dir, "--out-url",
                             "file://" + dir + "/images.lcmlog?mode=w"},
                            120);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto frames = Messages<widestereo::stereo_frame_t>(ReadLog(dir + "/images.lcmlog"),
                                                           channel::kStereoImages);
  ASSERT_EQ(frames.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(frames[i].frame_id, i);
    const auto [left, right] = DefaultSimulator().Render(i);
    EXPECT_EQ(cv::norm(ImageToMat(frames[i].left), left, cv::NORM_INF), 0) << i;
    EXPECT_EQ(cv::norm(ImageToMat(frames[i].right), right, cv::NORM_INF), 0) << i;
  }
  const SimTruth truth = LoadSimTruth(dir + "/truth.yaml");
  EXPECT_EQ(truth.frames.size(), 35u);
  EXPECT_EQ(truth.frames[2].left.corners, DefaultSimulator().FrameTruth(2).left.corners);
}

TEST(SimCapture, BadConfigEndsTheProcessWithTheReason) {
  const std::string dir = TempDir("sim-capture-bad");
  std::ofstream(dir + "/bad.yaml") << "rig: {baseline: 0.3, left: {lens: theia}}\nscene: {wall: {frames: 0}}\n";
  const auto r = RunCommand({"stereo-capture", "--source", "sim:" + dir + "/bad.yaml", "--log-dir", dir}, 60);
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("stereo-capture: " + dir + "/bad.yaml: scene.wall.frames"), std::string::npos) << r.output;
}

}  // namespace
