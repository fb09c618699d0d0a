#include "wall_chain.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>
#include <cstdio>

#include "lcm_io/channels.h"
#include "lcm_io/image_codec.h"
#include "match_fixtures.h"
#include "rig/rig_file.h"
#include "test_support.h"
#include "widestereo/cloud_stats_t.hpp"
#include "widestereo/disparity_t.hpp"

namespace ws::test {

SimTruth CaptureWall(const std::string& dir, const std::string& config, int frames) {
  const auto r = RunCommand({"stereo-capture", "--source", "sim:" + config + "?truth=" + dir + "/truth.yaml",
                             "--count", std::to_string(frames), "--rate", "10", "--frame-clock",
                             "--log-dir", dir, "--out-url", "file://" + dir + "/images.lcmlog?mode=w"},
                            120);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return LoadSimTruth(dir + "/truth.yaml");
}

ChainLogs RunMatchAndCloud(const std::string& dir, const Rig& rig, const std::string& name,
                           const std::string& num_disparities, const WallChainOptions& options) {
  const std::string calib = dir + "/" + name + ".yaml";
  const ChainLogs logs{dir + "/" + name + "-match.lcmlog", dir + "/" + name + "-cloud.lcmlog"};
  WriteCalibrationFile(calib, rig);
  std::vector<std::string> argv = {"stereo-match", "--log-dir", dir, "--config", options.match_config,
                                    "--calib", calib, "--num-disparities", num_disparities, "--focal-scale",
                                    std::to_string(options.focal_scale), "--rectification",
                                    RectificationModeName(options.mode), "--in-url",
                                    "file://" + dir + "/images.lcmlog?speed=0", "--out-url",
                                    "file://" + logs.match + "?mode=w"};
  argv.insert(argv.end(), options.match_args.begin(), options.match_args.end());
  auto r = RunCommand(argv, 120);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  argv = {"stereo-cloud", "--log-dir", dir, "--config", options.cloud_config, "--in-url",
          "file://" + logs.match + "?speed=0", "--out-url", "file://" + logs.cloud + "?mode=w"};
  argv.insert(argv.end(), options.cloud_args.begin(), options.cloud_args.end());
  r = RunCommand(argv, 120);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return logs;
}

namespace {

// The disparity against the truth on the full-resolution grid: one n times
// coarser (stereo-match --downscale n rectifies and matches there) scaled back
// by nearest neighbour, each coarse pixel's disparity (times n) on its n x n
// full-resolution pixels, so that every mode is measured alike.
DisparityErrors CompareToTruth(const cv::Mat& disparity, const cv::Mat& true_disparity) {
  if (disparity.size() == true_disparity.size()) return CompareDisparity(disparity, true_disparity);
  const int n = int(std::lround(double(true_disparity.cols) / disparity.cols));
  cv::Mat full;
  cv::resize(disparity * n, full, cv::Size(disparity.cols * n, disparity.rows * n), 0, 0, cv::INTER_NEAREST);
  EXPECT_EQ(full.size(), true_disparity.size());
  return CompareDisparity(full(cv::Rect(cv::Point(), true_disparity.size())), true_disparity);
}

}  // namespace

WallRun RunWallChain(const std::string& dir, const SimTruth& truth, const Rig& rig,
                     const std::string& name, int frames, const std::string& num_disparities,
                     const WallChainOptions& options) {
  const ChainLogs logs = RunMatchAndCloud(dir, rig, name, num_disparities, options);
  // The truth, seen through the true rig's rectification (the frame the
  // cloud is in only differs by the calibration's own rectifying rotation,
  // which is the same here: both calibrations share R and T).
  const Rig& true_rig = truth.rig;
  const Rectification rect = BuildRectification(true_rig, RectifyOptions{options.focal_scale, {}, options.mode});
  const SimFrameTruth& wall = truth.frames.front();
  const cv::Mat true_disparity = TrueWallDisparity(rect, true_rig, wall.wall_normal, wall.wall_offset);
  const cv::Vec3d normal = rect.R_left * wall.wall_normal;

  const auto match_events = ReadLog(logs.match);
  const auto disparities = Messages<widestereo::disparity_t>(match_events, channel::kStereoDisparity);
  const auto cloud_events = ReadLog(logs.cloud);
  const auto clouds = Messages<widestereo::point_cloud_t>(cloud_events, channel::kStereoCloudFiltered);
  const auto stats = Messages<widestereo::cloud_stats_t>(cloud_events, channel::kCloudStats);
  EXPECT_EQ(disparities.size(), size_t(frames));
  EXPECT_EQ(clouds.size(), size_t(frames));
  EXPECT_EQ(stats.size(), size_t(frames));
  WallRun run;
  for (size_t i = 0; i < std::min({disparities.size(), clouds.size(), stats.size()}); ++i) {
    EXPECT_TRUE(stats[i].plane_found) << name << " frame " << i;
    run.disparity.push_back(CompareToTruth(ImageToMat(disparities[i].disparity), true_disparity));
    run.wall.push_back(MeasureWall(clouds[i], stats[i], rect, true_disparity, normal, wall.wall_offset,
                                   0.02));
    const auto& d = run.disparity.back();
    const auto& w = run.wall.back();
    std::printf("[ wall ] %-7s frame %zu: disparity density %.3f, bias %+.3f px, sigma %.3f px, bad %.4f | "
                "plane %.4f m, tilt %.2f mrad, inlier RMS %.2f mm, inliers %.3f, RMS to truth %.2f mm, "
                "coverage %.3f | stages",
                name.c_str(), i, d.density, d.bias, d.sigma, d.bad_rate, w.offset, 1000 * w.tilt_rad,
                1000 * w.inlier_rms, w.inlier_fraction, 1000 * w.rms_to_truth, w.coverage);
    for (int s = 0; s < stats[i].nstages; ++s) std::printf(" %d", stats[i].stage_points[s]);
    std::printf("\n");
  }
  return run;
}

}  // namespace ws::test
