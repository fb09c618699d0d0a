// Real fisheye data no one here made (../shared/data, see its README): the
// ~185-degree stereo set of ros-perception/image_pipeline, through the real
// processes (stereo-capture dir: -> stereo-detect -> stereo-calibrate),
// against cv::fisheye::calibrate (Kannala-Brandt, 4 coefficients) on the same
// detections, and stereo-detect's boards and corners against OpenCV's own
// detector's; and BabelCalib's ov_plane set (~190 degrees) under its own
// train/test protocol, its corners refined as stereo-detect refines them.
// Skips, saying why, where the data are absent (a fresh clone).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>

#include "calib/calibrate.h"
#include "calib/evaluate/heldout.h"
#include "calib/node/corner_import.h"
#include "calib/node/corners_message.h"
#include "calib_process_support.h"
#include "detect/corner_refinement.h"
#include "detect/stereo_corner_finder.h"
#include "lcm_io/image_codec.h"
#include "rig/rig_file.h"

namespace {

using namespace ws;
using namespace ws::calib;
using namespace ws::calib::test;

std::string SharedData(const std::string& set) {
  return ws::test::SourceDir() + "/../shared/data/" + set;
}

struct OpenCvFisheye {
  double rms = 0;
  int views = 0;
};

// cv::fisheye::calibrate as OpenCV's own samples call it (recomputed
// extrinsics, no skew), on one camera's views.
OpenCvFisheye OpenCvFisheyeRms(const CameraData& camera) {
  std::vector<std::vector<cv::Point3d>> object;
  std::vector<std::vector<cv::Point2d>> image;
  OpenCvViews(camera, &object, &image);
  cv::Matx33d K;
  cv::Vec4d D;
  std::vector<cv::Vec3d> rvecs, tvecs;
  const double rms = cv::fisheye::calibrate(
      object, image, cv::Size(camera.image_width, camera.image_height), K, D, rvecs, tvecs,
      cv::fisheye::CALIB_RECOMPUTE_EXTRINSIC | cv::fisheye::CALIB_FIX_SKEW,
      cv::TermCriteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 100, 1e-10));
  return {rms, static_cast<int>(object.size())};
}

class RealFisheyeStereo : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!std::filesystem::is_directory(SharedData("fisheye-stereo-ros")))
      GTEST_SKIP() << SharedData("fisheye-stereo-ros")
                   << " is absent (real data beside the project, not part of it): skipped";
  }
};

TEST_F(RealFisheyeStereo, AngleModelsUseEveryViewAndBsplineThetaFitsNoWorseThanCvFisheye) {
  const std::string dir = ws::test::TempDir("calibrate-fisheye-ros");
  const std::string corners =
      CaptureAndDetect(dir, "dir:" + SharedData("fisheye-stereo-ros"), "chessboard:8x6:0.04");
  const StereoData data = ReadCorners(corners);
  const OpenCvFisheye opencv[2] = {OpenCvFisheyeRms(data.left), OpenCvFisheyeRms(data.right)};
  // The data's README: OpenCV's detector finds 46 left and 45 right boards;
  // stereo-detect finds at least those.
  EXPECT_GE(opencv[0].views, 46);
  EXPECT_GE(opencv[1].views, 45);
  // Every image of the set is a view, even the two nearly alike.
  const auto run = CalibrateOnce(dir, corners, "fisheye",
                                 {"--model", "all", "--flow", "paper", "--duplicate-px", "0.001",
                                  "--plot-dir", dir});
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const nlohmann::json report = ReadJson(dir + "/fisheye.json");
  std::printf("fisheye-stereo-ros, paper flow, per camera: RMS px (views, outliers)\n");
  std::printf("%-14s %24s %24s\n", "model", "left", "right");
  std::printf("%-14s %15.4f (%2d, %2d) %15.4f (%2d, %2d)\n", "cv::fisheye", opencv[0].rms,
              opencv[0].views, 0, opencv[1].rms, opencv[1].views, 0);
  for (const auto& model : report["models"]) {
    if (model.contains("error")) {
      std::printf("%-14s failed: %s\n", model["model"].get<std::string>().c_str(),
                  model["error"].get<std::string>().c_str());
      continue;
    }
    const auto& l = model["cameras"][0];
    const auto& r = model["cameras"][1];
    std::printf("%-14s %15.4f (%2d, %2d) %15.4f (%2d, %2d)\n",
                model["model"].get<std::string>().c_str(), l["rms_px"].get<double>(),
                l["views"].get<int>(), l["outliers"].get<int>(), r["rms_px"].get<double>(),
                r["views"].get<int>(), r["outliers"].get<int>());
    if (model["model"] != "bspline_theta" && model["model"] != "kb4") continue;
    for (int c = 0; c < 2; ++c) {
      const auto& camera = model["cameras"][c];
      EXPECT_EQ(camera["views"].get<int>(), opencv[c].views) << model["model"] << " " << c;
      if (model["model"] == "bspline_theta") {
        EXPECT_LE(camera["rms_px"].get<double>(), opencv[c].rms) << camera["name"];
      }
    }
  }
}

// kb4 (cv::fisheye's model) as the corner accuracy's yardstick: no outlier
// rejection and a flat board, so that every corner counts as it is.
CameraCalibration FitKb4(const CameraData& data) {
  CalibrationOptions options;
  options.model = ModelKind::kKb4;
  options.outliers = ws::calib::OutlierRule::kOff;
  options.board_warp = ws::calib::WarpRule::kFlat;
  options.nonradial = ws::calib::FieldRule::kNone;
  options.covariance = false;
  options.cv_folds = 0;
  return CalibrateCamera(data, options);
}

// stereo-detect's chessboard detector against OpenCV's own
// (findChessboardCorners with adaptive threshold and normalisation, then
// cornerSubPix) on every image: at least the boards OpenCV finds, every one
// of them a view of the calibration, and corners that kb4 fits no worse on
// the views both found.
TEST_F(RealFisheyeStereo, StereoDetectFindsOpenCvsBoardsAndItsCornersFitNoWorse) {
  const BoardSpec board = ParseBoardSpec("chessboard:8x6:0.04");
  const StereoCornerFinder ours(board, ChessboardMethod::classic), opencv(board, ChessboardMethod::opencv);
  const int opencv_boards_in_readme[2] = {46, 45};
  int c = 0;
  for (const std::string camera : {"left", "right"}) {
    std::vector<cv::String> files;
    cv::glob(SharedData("fisheye-stereo-ros") + "/" + camera + "-*.png", files);
    ASSERT_EQ(files.size(), 46u);
    CameraData all, both_ours, both_opencv;
    int opencv_boards = 0;
    for (const cv::String& file : files) {
      const cv::Mat gray = cv::imread(file, cv::IMREAD_GRAYSCALE);
      ASSERT_FALSE(gray.empty()) << file;
      for (CameraData* data : {&all, &both_ours, &both_opencv}) {
        data->image_width = gray.cols;
        data->image_height = gray.rows;
      }
      const widestereo::image_t image = MatToImage(gray, 0);
      const BoardView mine = ToBoardView(ours.FindInImage(image)), theirs = ToBoardView(opencv.FindInImage(image));
      opencv_boards += !theirs.empty();
      if (!mine.empty()) all.views.push_back(mine);
      if (!mine.empty() && !theirs.empty()) {
        both_ours.views.push_back(mine);
        both_opencv.views.push_back(theirs);
      }
    }
    const CameraCalibration every = FitKb4(all), mine = FitKb4(both_ours), theirs = FitKb4(both_opencv);
    std::printf("%s: boards stereo-detect %zu, OpenCV %d; kb4 on the %zu both found: stereo-detect's corners "
                "%.4f px, OpenCV's %.4f px\n",
                camera.c_str(), all.views.size(), opencv_boards, both_ours.views.size(), mine.rms_px,
                theirs.rms_px);
    EXPECT_EQ(opencv_boards, opencv_boards_in_readme[c++]);
    EXPECT_GE(static_cast<int>(all.views.size()), opencv_boards);
    EXPECT_EQ(every.views, static_cast<int>(all.views.size())) << "every board found is a view";
    EXPECT_LE(mine.rms_px, theirs.rms_px);
  }
}

// The .orpc files of a folder, in name order.
std::vector<std::string> OrpcFiles(const std::string& dir) {
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    if (entry.path().extension() == ".orpc") files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

// BabelCalib's protocol: calibrate on train with the defaults (every model,
// the one with the lowest held-out RMS, its knots, bow, field and outliers
// chosen from the data); hold the camera, fit each test pose alone to all
// its corners, and report the test RMS. mrcal 2.2's splined model on the
// same corners reaches 0.355 px (bench/real/README.md). Measured: 0.353 px,
// bspline_theta with an 11 x 7 field and the board's bow.
TEST(RealBabelCalib, TrainTestProtocolWithTheDefaultsNoWorseThanMrcal) {
  const std::string dir = SharedData("babelcalib-ov-plane");
  if (!std::filesystem::is_directory(dir))
    GTEST_SKIP() << dir << " is absent (real data beside the project, not part of it): skipped";
  StereoData train;
  train.left = ReadBabelCalibViews(dir + "/ov_plane.dsc", OrpcFiles(dir + "/corners/train"));
  train.right.views.resize(train.left.views.size());  // one camera
  const CameraData test =
      ReadBabelCalibViews(dir + "/ov_plane.dsc", OrpcFiles(dir + "/corners/test"));
  ASSERT_EQ(train.size(), 18);
  ASSERT_EQ(test.views.size(), 7u);
  const ModelCalibrations all = CalibrateStereoAllModels(train, CalibrationOptions(), ModelKinds());
  const CameraCalibration& chosen = Chosen(all).left;
  const HeldOutFit held_out = FitHeldOutViews(chosen.model, test, 6, chosen.board_warp);
  std::printf("babelcalib ov_plane (BabelCalib's protocol), defaults: %s, field %d x %d, train %.4f px "
              "(%d views, %d outliers), test %.4f px (%d views)\n",
              ModelName(Chosen(all).model).c_str(), chosen.model.nonradial.cols, chosen.model.nonradial.rows,
              chosen.rms_px, chosen.views, chosen.outliers, held_out.rms_px, held_out.views);
  EXPECT_EQ(chosen.views, 18);
  EXPECT_EQ(held_out.views, 7);
  EXPECT_LE(held_out.rms_px, 0.355);
}

// The same train views through the processes, as a user calibrates corners
// found by another tool: stereo-import-corners -> stereo-calibrate, a
// one-camera rig (the report has "left" only and no "stereo").
TEST(RealBabelCalib, ImportedCornersCalibrateAsAOneCameraRig) {
  const std::string data = SharedData("babelcalib-ov-plane");
  if (!std::filesystem::is_directory(data))
    GTEST_SKIP() << data << " is absent (real data beside the project, not part of it): skipped";
  const std::string dir = ws::test::TempDir("import-babelcalib-process");
  std::vector<std::string> import = {"stereo-import-corners", "--babelcalib",
                                     data + "/ov_plane.dsc", "--log-dir", dir, "--quiet",
                                     "--out-url", FileUrl(dir + "/corners.lcmlog", "mode=w")};
  for (const auto& orpc : OrpcFiles(data + "/corners/train")) import.push_back(orpc);
  const auto imported = ws::test::RunCommand(import, 60);
  ASSERT_EQ(imported.exit_code, 0) << imported.output;
  // Every imported view counts, the nearly alike ones too.
  const auto run = CalibrateOnce(dir, dir + "/corners.lcmlog", "mono",
                                 {"--model", "bspline_theta", "--duplicate-px", "0.001"});
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const nlohmann::json report = ReadJson(dir + "/mono.json");
  ASSERT_EQ(report["cameras"].size(), 1u);
  EXPECT_EQ(report["cameras"][0]["name"], "left");
  EXPECT_EQ(report["cameras"][0]["views"], 18);
  EXPECT_FALSE(report.contains("stereo"));
  const Rig file = ReadCalibrationFile(dir + "/mono.yaml");
  EXPECT_TRUE(file.mono);
  EXPECT_EQ(file.left.distortion.kind, ModelKind::kBsplineTheta);
  EXPECT_EQ(file.left.image_width, 1280);
}

// BabelCalib's corners of the train views refined as stereo-detect refines
// a detection (the saddle points, from there, falling back to cornerSubPix)
// and as OpenCV's detector does (cornerSubPix alone): kb4 fits the first no
// worse. (OpenCV's detectors find none of this board, whose tags break its
// squares.)
TEST(RealBabelCalib, SaddlePointsFromItsCornersFitNoWorseThanCornerSubPix) {
  const std::string dir = SharedData("babelcalib-ov-plane");
  if (!std::filesystem::is_directory(dir))
    GTEST_SKIP() << dir << " is absent (real data beside the project, not part of it): skipped";
  const std::vector<std::string> orpc = OrpcFiles(dir + "/corners/train");
  const CameraData given = ReadBabelCalibViews(dir + "/ov_plane.dsc", orpc);
  CameraData subpix = given, saddle = given;
  for (size_t v = 0; v < orpc.size(); ++v) {
    const std::string image = orpc[v].substr(0, orpc[v].rfind('.')) + ".png";
    const cv::Mat gray = cv::imread(image, cv::IMREAD_GRAYSCALE);
    ASSERT_FALSE(gray.empty()) << image;
    const std::vector<double> spacing = NeighbourSpacing(given.views[v]);
    std::vector<cv::Point2f> points, fallback;
    for (const auto& p : given.views[v].image) points.emplace_back(float(p.x()), float(p.y()));
    fallback = points;
    CornerSubPix(gray, fallback, spacing);
    RefineCorners(gray, points, spacing, fallback);
    for (size_t i = 0; i < points.size(); ++i) {
      subpix.views[v].image[i] = {fallback[i].x, fallback[i].y};
      saddle.views[v].image[i] = {points[i].x, points[i].y};
    }
  }
  const CameraCalibration mine = FitKb4(saddle), theirs = FitKb4(subpix), as_given = FitKb4(given);
  std::printf("babelcalib train views, kb4: saddle points %.4f px, cornerSubPix %.4f px, BabelCalib's own "
              "corners %.4f px\n",
              mine.rms_px, theirs.rms_px, as_given.rms_px);
  EXPECT_LE(mine.rms_px, theirs.rms_px);
}

}  // namespace
