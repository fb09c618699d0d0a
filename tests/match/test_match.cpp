// stereo-match: rectification geometry through the full lens model, the
// Middlebury aloe pair against bare OpenCV SGBM in the same test, bad input.
#include <gtest/gtest.h>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "lcm_io/channels.h"
#include "lcm_io/image_codec.h"
#include "match/match_node.h"
#include "match_fixtures.h"
#include "models/model_registry.h"
#include "models/theia_lens.h"
#include "rig/rig_message.h"
#include "test_support.h"
#include "widestereo/disparity_t.hpp"
#include "widestereo/process_status_t.hpp"

namespace {

using namespace ws::test;

// The Theia-like mustache lens on both sides, 0.3 m baseline, a slightly
// rotated and offset right camera.
ws::Rig WideRig() {
  ws::Rig rig;
  rig.left = rig.right = ws::TheiaLikeCamera();
  rig.right.fx *= 1.01;
  rig.right.cx += 3;
  cv::Matx33d R;
  cv::Rodrigues(cv::Vec3d(0.01, -0.02, 0.005), R);
  for (int i = 0; i < 9; ++i) rig.R(i / 3, i % 3) = R.val[i];
  rig.T = Eigen::Vector3d(-0.3, 0.004, 0.002);
  return rig;
}

TEST(Rectification, CorrespondingPixelsShareARowAcrossTheWholeField) {
  const ws::Rig rig = WideRig();
  const ws::Rectification rect = ws::BuildRectification(rig);
  EXPECT_NEAR(rect.baseline, rig.T.norm(), 1e-12);
  const ws::Camera left(rig.left), right(rig.right);
  int checked = 0;
  double worst_row = 0, worst_depth = 0;
  for (double depth : {1.0, 2.0, 5.0}) {
    for (int v = 0; v < 960; v += 60) {
      for (int u = 0; u < 1280; u += 80) {
        // A scene point seen at (u, v) by the left camera, at this depth.
        const auto ray = left.Unproject(Eigen::Vector2d(u, v));
        ASSERT_TRUE(ray);
        const Eigen::Vector3d X = *ray * (depth / (*ray)(2));
        const auto pr = right.Project(rig.R * X + rig.T);
        if (!pr || (*pr)(0) < 0 || (*pr)(0) > 1279 || (*pr)(1) < 0 || (*pr)(1) > 959) continue;
        cv::Point2d l, r;
        ASSERT_TRUE(ws::RectifyPoint(rect, rig, true, cv::Point2d(u, v), &l));
        ASSERT_TRUE(ws::RectifyPoint(rect, rig, false, cv::Point2d((*pr)(0), (*pr)(1)), &r));
        worst_row = std::max(worst_row, std::abs(l.y - r.y));
        // The disparity gives back the depth along the rectified axis.
        const cv::Vec3d Xr = rect.R_left * cv::Vec3d(X(0), X(1), X(2));
        worst_depth = std::max(worst_depth, std::abs(rect.f * rect.baseline / (l.x - r.x) - Xr[2]));
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 300);
  EXPECT_LT(worst_row, 1e-6);
  EXPECT_LT(worst_depth, 1e-6);
}

TEST(Rectification, RemapTablesAgreeWithTheModel) {
  const ws::Rig rig = WideRig();
  const ws::Rectification rect = ws::BuildRectification(rig);
  cv::Mat map_x, map_y;
  cv::convertMaps(rect.maps_right[0][0], rect.maps_right[0][1], map_x, map_y, CV_32FC1);
  double worst = 0;
  for (int v = 40; v < 960; v += 97) {
    for (int u = 40; u < 1280; u += 101) {
      cv::Point2d rectified;
      ASSERT_TRUE(ws::RectifyPoint(rect, rig, false, cv::Point2d(u, v), &rectified));
      const int ru = int(std::lround(rectified.x)), rv = int(std::lround(rectified.y));
      if (ru < 0 || rv < 0 || ru >= rect.size.width || rv >= rect.size.height) continue;
      // The table maps the rectified pixel back to near (u, v): within the
      // rounding of the rectified pixel (<= 0.5 px there) and the fixed-point
      // step (1/32 px).
      cv::Point2d back;
      ASSERT_TRUE(ws::RectifyPoint(rect, rig, false,
                                   cv::Point2d(map_x.at<float>(rv, ru), map_y.at<float>(rv, ru)), &back));
      worst = std::max(worst, cv::norm(back - cv::Point2d(ru, rv)));
    }
  }
  EXPECT_LT(worst, 0.05);
}

TEST(Rectification, IdentityCalibrationLeavesImagesUntouched) {
  const cv::Mat left = cv::imread(std::string(kOpenCvDataDir) + "/aloeL.jpg");
  const cv::Mat right = cv::imread(std::string(kOpenCvDataDir) + "/aloeR.jpg");
  const auto rig = ws::RigFromMessage(IdentityCalibration(left.cols, left.rows, 1000, 0.1));
  const ws::Rectification rect = ws::BuildRectification(rig);
  cv::Mat lr, rr;
  ws::RectifyPair(rect, left, right, &lr, &rr);
  EXPECT_EQ(cv::norm(lr, left, cv::NORM_INF), 0);
  EXPECT_EQ(cv::norm(rr, right, cv::NORM_INF), 0);
}

TEST(DisparityCloud, StepKeepsEveryNthPixelOfEveryNthRow) {
  const auto rig = ws::RigFromMessage(IdentityCalibration(64, 48, 100, 0.1));
  const ws::Rectification rect = ws::BuildRectification(rig);
  const cv::Mat disparity(48, 64, CV_32FC1, cv::Scalar(10.0f));  // every pixel at Z = 100 * 0.1 / 10 = 1 m
  const cv::Mat gray(48, 64, CV_8UC1, cv::Scalar(7));
  const auto full = ws::DisparityToCloud(rect, disparity, 0, gray, {20.0, 1});
  const auto sparse = ws::DisparityToCloud(rect, disparity, 0, gray, {20.0, 4});
  ASSERT_EQ(full.npoints, 64 * 48);
  ASSERT_EQ(sparse.npoints, 16 * 12);
  EXPECT_EQ(sparse.nintensity, sparse.npoints);
  for (int i = 0; i < sparse.npoints; ++i) {
    EXPECT_FLOAT_EQ(sparse.xyz[i][2], 1.0f);
    const double u = sparse.xyz[i][0] * rect.f + rect.cx, v = sparse.xyz[i][1] * rect.f + rect.cy;
    EXPECT_NEAR(u, 4 * std::round(u / 4), 1e-3) << "a point between the sampled columns";
    EXPECT_NEAR(v, 4 * std::round(v / 4), 1e-3) << "a point between the sampled rows";
  }
  EXPECT_EQ(ws::DisparityToCloud(rect, disparity, 0, gray, {0.5, 1}).npoints, 0) << "all beyond max_depth";
}

// On a grid n times coarser (stereo-match --downscale) the cloud samples the
// full-resolution pixels a full-size disparity would give: a slanted plane's
// disparity, on the full grid and on the half grid (each coarse pixel the
// mean of the 2 x 2 it covers), gives the same points at step 4, at the same
// image positions. The first row and column (full-resolution 0, a quarter
// of a coarse pixel outside the coarse grid's first centre) take the
// disparity of the coarse pixels inside: within the slope's quarter pixel.
TEST(DisparityCloud, ACoarseGridSamplesTheFullResolutionPositions) {
  const auto rig = ws::RigFromMessage(IdentityCalibration(64, 48, 100, 0.1));
  ws::RectifyOptions options;
  const ws::Rectification full_rect = ws::BuildRectification(rig, options);
  options.downscale = 2;
  const ws::Rectification coarse_rect = ws::BuildRectification(rig, options);
  ASSERT_EQ(coarse_rect.size, cv::Size(32, 24));
  // D(U, V) = 10 + 0.05 U + 0.02 V full-resolution pixels; a coarse pixel's
  // disparity is the full one at its centre (2 u + 1/2, 2 v + 1/2), halved.
  auto plane = [](double U, double V) { return 10 + 0.05 * U + 0.02 * V; };
  cv::Mat full(48, 64, CV_32FC1), coarse(24, 32, CV_32FC1);
  for (int V = 0; V < 48; ++V)
    for (int U = 0; U < 64; ++U) full.at<float>(V, U) = float(plane(U, V));
  for (int v = 0; v < 24; ++v)
    for (int u = 0; u < 32; ++u) coarse.at<float>(v, u) = float(plane(2 * u + 0.5, 2 * v + 0.5) / 2);
  const auto a = ws::DisparityToCloud(full_rect, full, 0, {}, {20.0, 4});
  const auto b = ws::DisparityToCloud(coarse_rect, coarse, 0, {}, {20.0, 4});
  ASSERT_EQ(a.npoints, 16 * 12);
  ASSERT_EQ(b.npoints, a.npoints);
  for (int k = 0; k < a.npoints; ++k) {
    const int i = k % 16, j = k / 16;
    const cv::Vec3d pa(a.xyz[k][0], a.xyz[k][1], a.xyz[k][2]), pb(b.xyz[k][0], b.xyz[k][1], b.xyz[k][2]);
    // Full-resolution pixel (4 i, 4 j), whatever the grid.
    EXPECT_NEAR(pb[0] / pb[2] * full_rect.f + full_rect.cx, 4 * i, 1e-3) << k;
    EXPECT_NEAR(pb[1] / pb[2] * full_rect.f + full_rect.cy, 4 * j, 1e-3) << k;
    if (i > 0 && j > 0)
      EXPECT_LT(cv::norm(pa - pb), 1e-5) << "full-resolution pixel (" << 4 * i << ", " << 4 * j << ")";
    else  // a quarter coarse pixel of both slopes: at most 0.035 px of the 10 to 13 px disparity
      EXPECT_NEAR(pb[2] / pa[2], 1, 0.004) << k;
  }
  // An edge: 10 | 20 coarse pixels. No point between the two depths.
  coarse.setTo(10.0f);
  coarse.colRange(16, 32).setTo(20.0f);
  const auto edge = ws::DisparityToCloud(coarse_rect, coarse, 0, {}, {20.0, 4});
  ASSERT_EQ(edge.npoints, 16 * 12);
  const double z10 = coarse_rect.f * 0.1 / 10, z20 = coarse_rect.f * 0.1 / 20;
  for (const auto& p : edge.xyz)
    EXPECT_TRUE(std::abs(p[2] - z10) < 1e-5 || std::abs(p[2] - z20) < 1e-5) << p[2];
}

struct Score {
  double bad_rate;  // of pixels with ground truth and an estimate: |d - gt| > 1 px
  double density;   // of pixels with ground truth: those with an estimate
};

// Over columns first_column and right of it.
Score ScoreAgainstGroundTruth(const cv::Mat& disparity, const cv::Mat& gt, float invalid_below,
                              int first_column = 0) {
  int known = 0, estimated = 0, bad = 0;
  for (int v = 0; v < gt.rows; ++v)
    for (int u = first_column; u < gt.cols; ++u) {
      const int g = gt.at<uint8_t>(v, u);
      if (g == 0) continue;
      ++known;
      const float d = disparity.at<float>(v, u);
      if (d < invalid_below) continue;
      ++estimated;
      bad += std::abs(d - g) > 1.0f;
    }
  return {double(bad) / estimated, double(estimated) / known};
}

TEST(MatchPipeline, AloeGivesWhatBareOpenCvSgbmGives) {
  const std::string dir = TempDir("aloe");
  const cv::Mat left = cv::imread(std::string(kOpenCvDataDir) + "/aloeL.jpg");
  const cv::Mat right = cv::imread(std::string(kOpenCvDataDir) + "/aloeR.jpg");
  const cv::Mat gt = cv::imread(std::string(kOpenCvDataDir) + "/aloeGT.png", cv::IMREAD_UNCHANGED);
  ASSERT_FALSE(left.empty() || right.empty() || gt.empty());

  widestereo::stereo_frame_t frame{};
  frame.utime = 2000000;
  frame.left = ws::MatToImage(left, frame.utime, ws::Compression::png);
  frame.right = ws::MatToImage(right, frame.utime, ws::Compression::png);
  auto calib = IdentityCalibration(left.cols, left.rows, 1000, 0.1);
  calib.utime = 1000000;
  WriteLog(dir + "/in.lcmlog", {Event(ws::channel::kStereoCalibration, calib),
                                Event(ws::channel::kStereoImages, frame)});

  ws::MatcherConfig config;  // the pipeline's settings, but for the range
  config.kind = "sgbm3way";  // stereo-match's default
  config.num_disparities = 224;
  const auto r = RunCommand({"stereo-match", "--log-dir", dir, "--num-disparities", "224",
                             "--max-depth", "1000", "--cloud-step", "1", "--in-url", "file://" + dir + "/in.lcmlog?speed=0",
                             "--out-url", "file://" + dir + "/out.lcmlog?mode=w"},
                            300);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto events = ReadLog(dir + "/out.lcmlog");
  const auto disparities = Messages<widestereo::disparity_t>(events, ws::channel::kStereoDisparity);
  ASSERT_EQ(disparities.size(), 1u);
  const cv::Mat pipeline = ws::ImageToMat(disparities[0].disparity);

  cv::Mat gray_left, gray_right, fixed_point, bare;
  cv::cvtColor(left, gray_left, cv::COLOR_BGR2GRAY);
  cv::cvtColor(right, gray_right, cv::COLOR_BGR2GRAY);
  ws::MakeMatcher(config)->compute(gray_left, gray_right, fixed_point);
  fixed_point.convertTo(bare, CV_32F, 1.0 / 16);

  // Bare SGBM gives nothing in the first num_disparities columns; the
  // pipeline matches them too (DisparityMatcher's margin) and elsewhere
  // gives what bare SGBM gives.
  const Score ours = ScoreAgainstGroundTruth(pipeline, gt, 0);
  const Score opencv = ScoreAgainstGroundTruth(bare, gt, 0);
  const Score ours_right = ScoreAgainstGroundTruth(pipeline, gt, 0, config.num_disparities);
  const Score opencv_right = ScoreAgainstGroundTruth(bare, gt, 0, config.num_disparities);
  std::printf("aloe: pipeline bad %.4f density %.4f | bare SGBM bad %.4f density %.4f | right of the first %d "
              "columns: pipeline bad %.4f density %.4f, bare bad %.4f density %.4f\n",
              ours.bad_rate, ours.density, opencv.bad_rate, opencv.density, config.num_disparities,
              ours_right.bad_rate, ours_right.density, opencv_right.bad_rate, opencv_right.density);
  EXPECT_NEAR(ours_right.bad_rate, opencv_right.bad_rate, 2e-3);
  EXPECT_NEAR(ours_right.density, opencv_right.density, 2e-3);
  EXPECT_GT(ours.density, opencv.density + 0.1);
  EXPECT_LT(ours.bad_rate, 0.2);
  EXPECT_GT(ours.density, 0.7);

  // The full cloud (on request) holds the valid disparities, in the left
  // rectified frame.
  const auto clouds = Messages<widestereo::point_cloud_t>(events, ws::channel::kStereoCloud);
  ASSERT_EQ(clouds.size(), 1u);
  EXPECT_EQ(clouds[0].frame, "left_rectified");
  EXPECT_EQ(clouds[0].npoints, cv::countNonZero(pipeline > 0));
  EXPECT_EQ(clouds[0].nintensity, clouds[0].npoints);
}

TEST(MatchPipeline, BadFramesAndFramesBeforeCalibrationAreCountedNotFatal) {
  const std::string dir = TempDir("badsize");
  widestereo::stereo_frame_t frame{};
  frame.left = frame.right = ws::MatToImage(cv::Mat(48, 64, CV_8UC1, cv::Scalar(7)), 1);
  std::vector<LogEvent> events;
  frame.frame_id = 0;
  frame.utime = 1000000;
  events.push_back(Event(ws::channel::kStereoImages, frame));  // before any calibration
  auto calib = IdentityCalibration(640, 480, 500, 0.1);        // for 640x480 frames
  calib.utime = 2000000;
  events.push_back(Event(ws::channel::kStereoCalibration, calib));
  frame.frame_id = 1;
  frame.utime = 3000000;
  events.push_back(Event(ws::channel::kStereoImages, frame));  // 64x48
  frame.frame_id = 2;
  frame.left.height = 480;  // height x row_stride disagrees with the payload
  events.push_back(Event(ws::channel::kStereoImages, frame));
  WriteLog(dir + "/in.lcmlog", events);
  const auto r = RunCommand({"stereo-match", "--log-dir", dir, "--in-url",
                             "file://" + dir + "/in.lcmlog?speed=0", "--out-url",
                             "file://" + dir + "/out.lcmlog?mode=w"},
                            60);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("frame 1 is 64x48 but the STEREO_CALIBRATION of utime 2000000 is for 640x480"),
            std::string::npos)
      << r.output;
  const auto c = LastCounters(dir + "/out.lcmlog", "stereo-match", ws::channel::kStereoImages);
  EXPECT_EQ(c.received, 3);
  EXPECT_EQ(c.dropped, 1);
  EXPECT_EQ(c.rejected, 2);
}

// Every model kind of the library works live: a calibration of each kind
// (no distortion for the ideal-plane models, the equidistant fisheye for the
// angle models: all their coefficients 0), published one after the other,
// each followed by a frame. stereo-match adopts each, builds its maps and
// matches the frame after it.
TEST(MatchPipeline, EveryModelKindIsAdoptedLive) {
  const std::string dir = TempDir("match-every-kind");
  cv::Mat texture(240, 320, CV_8UC1);
  cv::randu(texture, 0, 255);
  cv::GaussianBlur(texture, texture, cv::Size(3, 3), 0.8);
  widestereo::stereo_frame_t frame{};
  frame.left = ws::MatToImage(texture, 0);
  cv::Mat shifted;  // the right image: the scene 8 px to the left
  cv::copyMakeBorder(texture(cv::Rect(8, 0, 312, 240)), shifted, 0, 0, 0, 8, cv::BORDER_REPLICATE);
  frame.right = ws::MatToImage(shifted, 0);
  std::vector<LogEvent> events;
  int64_t utime = 1000000;
  for (const ws::ModelKind kind : ws::ModelKinds()) {
    const ws::Distortion d = std::visit(
        [](const auto& model) {
          const std::vector<double> zeros(size_t(model.NumCoeffs()), 0.0);
          return model.ToData(zeros.data());
        },
        ws::MakeCalibrationModel(kind, {1.2, 6, 3}));
    auto calib = IdentityCalibration(320, 240, 200, 0.1);
    for (auto* camera : {&calib.left, &calib.right}) {
      camera->model = ws::ModelName(d.kind);
      camera->degree = d.degree;
      camera->knots = d.knots;
      camera->nknots = int(d.knots.size());
      camera->coeffs = d.coeffs;
      camera->ncoeffs = int(d.coeffs.size());
    }
    calib.utime = utime += 1000000;
    events.push_back(Event(ws::channel::kStereoCalibration, calib));
    frame.utime = frame.left.utime = frame.right.utime = utime += 1000000;
    ++frame.frame_id;
    events.push_back(Event(ws::channel::kStereoImages, frame));
  }
  WriteLog(dir + "/in.lcmlog", events);
  const auto r = RunCommand({"stereo-match", "--log-dir", dir, "--in-url", "file://" + dir + "/in.lcmlog?speed=0",
                             "--out-url", "file://" + dir + "/out.lcmlog?mode=w"},
                            120);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const std::string& kind : ws::ModelNames())
    EXPECT_NE(r.output.find(", " + kind + " model"), std::string::npos) << kind << "\n" << r.output;
  const auto out = ReadLog(dir + "/out.lcmlog");
  EXPECT_EQ(Messages<widestereo::disparity_t>(out, ws::channel::kStereoDisparity).size(), ws::ModelKinds().size());
  EXPECT_EQ(LastCounters(dir + "/out.lcmlog", "stereo-match", ws::channel::kStereoCalibration).rejected, 0);
}

}  // namespace
