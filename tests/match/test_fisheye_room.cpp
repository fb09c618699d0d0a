// The 200-degree angle-model rig inside the textured box room of
// config/sim/fisheye.yaml (issue #15): stereo-match (lat-lon, then a pinhole of the same
// focal length) -> stereo-cloud; every face's plane against the truth and
// how much of the common field both lenses see the cloud covers.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "cloud/cloud_filter_config.h"
#include "lcm_io/channels.h"
#include "lcm_io/image_codec.h"
#include "match_fixtures.h"
#include "room_analysis.h"
#include "test_support.h"
#include "wall_analysis.h"
#include "wall_chain.h"
#include "widestereo/disparity_t.hpp"

namespace {

using namespace ws::test;

TEST(FisheyeRoom, LatLonCoversTheCommonFieldAndFindsEveryWall) {
  const std::string dir = TempDir("fisheye-room");
  const ws::SimTruth truth = CaptureWall(dir, FisheyeSceneConfig(dir, "room"), 1);
  ASSERT_EQ(truth.frames.size(), 1u);
  const std::vector<cv::Vec4d>& planes = truth.frames[0].room_planes;
  ASSERT_EQ(planes.size(), 6u);
  const ws::Rig rig = truth.rig;
  const RoomField field = TrueRoomField(rig, planes);
  // The search range reaches the nearest face's disparity.
  double largest = 0;
  cv::minMaxLoc(field.disparity, nullptr, &largest);
  const std::string num_disparities = std::to_string((int(largest * 1.25) / 16 + 1) * 16);
  ws::CloudFilterConfig cloud_config;  // config/stereo-cloud.yaml's plane fit
  const struct {
    ws::RectificationMode mode;
    const char* name;
  } modes[2] = {{ws::RectificationMode::kLatLon, "latlon"}, {ws::RectificationMode::kPinhole, "pinhole"}};
  RoomFit fits[2];
  for (int m = 0; m < 2; ++m) {
    WallChainOptions options;
    options.mode = modes[m].mode;
    // The lat-lon cloud reaches behind the image plane.
    options.cloud_args = {"--z-min", "-10"};
    const ChainLogs logs = RunMatchAndCloud(dir, rig, modes[m].name, num_disparities, options);
    const auto clouds = Messages<widestereo::point_cloud_t>(ReadLog(logs.cloud), ws::channel::kStereoCloudFiltered);
    const auto disparities = Messages<widestereo::disparity_t>(ReadLog(logs.match), ws::channel::kStereoDisparity);
    ASSERT_EQ(clouds.size(), 1u);
    ASSERT_EQ(disparities.size(), 1u);
    // The matcher's disparities against the truth in this mode's own image, face by face.
    const ws::Rectification rect = ws::BuildRectification(rig, {1.0, {}, modes[m].mode});
    cv::Mat face_of_pixel;
    const cv::Mat true_disparity = TrueSceneDisparity(rect, rig, planes, &face_of_pixel);
    const cv::Mat disparity = ws::ImageToMat(disparities[0].disparity);
    std::vector<DisparityErrors> face_errors;
    for (size_t k = 0; k < planes.size(); ++k) {
      cv::Mat on_face = cv::Mat::zeros(true_disparity.size(), CV_32FC1);
      true_disparity.copyTo(on_face, face_of_pixel == int(k));
      face_errors.push_back(CompareDisparity(disparity, on_face));
    }
    const RangeAccuracy accuracy = PredictRangeAccuracy(rect, true_disparity);
    fits[m] = MeasureRoom(clouds[0], field, cloud_config);
    std::printf("[ room ] %s (%d x %d): %d filtered points, coverage %.3f of the common field (%.1f x %.1f "
                "degrees); range change for a 0.1 px disparity error: %.1f mm at the centre, median %.1f mm, "
                "90th percentile %.1f mm\n",
                modes[m].name, rect.size.width, rect.size.height, clouds[0].npoints, fits[m].coverage,
                field.latlon.size.width / field.latlon.f * 180 / M_PI,
                field.latlon.size.height / field.latlon.f * 180 / M_PI, 1000 * accuracy.centre,
                1000 * accuracy.median, 1000 * accuracy.p90);
    for (size_t k = 0; k < planes.size(); ++k) {
      const FaceFit& f = fits[m].faces[k];
      const DisparityErrors& e = face_errors[k];
      std::printf("[ room ]   %-12s %.3f of the field, %7d points, disparity density %.3f bias %+.3f px sigma "
                  "%.3f px bad %.4f: ",
                  FaceName(planes[k]).c_str(), f.field_fraction, f.points, e.density, e.bias, e.sigma, e.bad_rate);
      if (f.found)
        std::printf("plane %.4f m (true %.4f m, %+.2f %%), tilt %.2f mrad, RMS %.2f mm\n", f.offset,
                    f.true_offset, 100 * (f.offset / f.true_offset - 1), 1000 * f.tilt_rad,
                    1000 * f.inlier_rms);
      else
        std::printf("no plane\n");
    }
  }
  const RoomFit& latlon = fits[0];
  EXPECT_GE(latlon.coverage, 0.9);
  EXPECT_GT(latlon.coverage, fits[1].coverage);
  for (size_t k = 0; k < planes.size(); ++k) {
    const FaceFit& f = latlon.faces[k];
    if (f.field_fraction < 0.01) continue;  // a face the common field hardly shows
    EXPECT_TRUE(f.found) << FaceName(planes[k]);
    EXPECT_NEAR(f.offset, f.true_offset, 0.01 * f.true_offset) << FaceName(planes[k]);
    EXPECT_LT(f.tilt_rad, 0.02) << FaceName(planes[k]);
  }
}

}  // namespace
