// A rig and its calibration message convert into each other.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "lcm_io/validate.h"
#include "rectify/stereo_rig.h"
#include "sim/sim_config.h"

namespace {

TEST(StereoRig, MessageOfARigGivesTheRigBack) {
  ws::StereoRig rig;
  rig.left = rig.right = ws::SimDefaultCamera(0.5);
  rig.right.fx *= 1.01;
  rig.right.distortion = ws::Distortion{ws::ModelKind::kPoly6, 0, {}, {-0.2, 0.05, -0.004}};
  rig.R = Eigen::AngleAxisd(0.02, Eigen::Vector3d(0, 1, 0)).toRotationMatrix();
  rig.T = Eigen::Vector3d(-0.3, 0.01, 0);
  const widestereo::stereo_calibration_t msg = ws::MessageFromStereoRig(rig, 42);
  EXPECT_NO_THROW(ws::Validate(msg));
  EXPECT_EQ(msg.utime, 42);
  EXPECT_EQ(msg.left.name, "left");
  EXPECT_EQ(msg.right.name, "right");
  const ws::StereoRig back = ws::StereoRigFromMessage(msg);
  for (const auto& [a, b] : {std::pair{&rig.left, &back.left}, std::pair{&rig.right, &back.right}}) {
    EXPECT_EQ(a->image_width, b->image_width);
    EXPECT_EQ(a->Intrinsics(), b->Intrinsics());
    EXPECT_EQ(a->distortion.kind, b->distortion.kind);
    EXPECT_EQ(a->distortion.knots, b->distortion.knots);
    EXPECT_EQ(a->distortion.coeffs, b->distortion.coeffs);
  }
  EXPECT_EQ(back.R, rig.R);
  EXPECT_EQ(back.T, rig.T);
}

}  // namespace
