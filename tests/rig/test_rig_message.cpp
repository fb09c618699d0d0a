// A rig and its calibration message convert into each other, every field
// of the camera table (models/camera_field_table.h) and its RMS figures
// with it.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "lcm_io/validate.h"
#include "models/camera_field_table.h"
#include "rig/rig_message.h"
#include "sim/sim_config.h"

namespace {

// Every field the camera table visits, by key, its value printed in full.
std::vector<std::pair<std::string, std::string>> TableFields(const ws::CameraModel& m) {
  std::vector<std::pair<std::string, std::string>> out;
  auto add = [&](auto& self, const std::string& key, const auto& value) -> void {
    using T = std::decay_t<decltype(value)>;
    std::ostringstream text;
    text.precision(17);
    if constexpr (std::is_same_v<T, ws::NonRadial>) {
      ws::ForEachNonRadialField(value, [&](const std::string& k, const auto& v) { self(self, key + "." + k, v); });
      return;
    } else if constexpr (std::is_same_v<T, ws::ModelKind>) {
      text << ws::ModelName(value);
    } else if constexpr (std::is_class_v<T>) {
      for (double v : value) text << v << " ";
    } else {
      text << value;
    }
    out.emplace_back(key, text.str());
  };
  ws::ForEachCameraField(m, [&](const std::string& key, const auto& value) { add(add, key, value); });
  return out;
}

TEST(RigMessage, MessageOfARigGivesTheRigBack) {
  ws::Rig rig;
  rig.left = rig.right = ws::SimDefaultCamera(0.5);
  rig.right.fx *= 1.01;
  rig.right.distortion = ws::Distortion{ws::ModelKind::kPoly6, 0, {}, {-0.2, 0.05, -0.004}};
  rig.left.nonradial = ws::NonRadial{4, 4, {-1.5, 1.5, -1, 1}, std::vector<double>(32, 1e-4), {0.01, -0.02}};
  rig.R = Eigen::AngleAxisd(0.02, Eigen::Vector3d(0, 1, 0)).toRotationMatrix();
  rig.T = Eigen::Vector3d(-0.3, 0.01, 0);
  rig.left_rms = 0.125;
  rig.right_rms = 0.25;
  rig.rms = 0.5;
  const widestereo::stereo_calibration_t msg = ws::MessageFromRig(rig, 42);
  EXPECT_NO_THROW(ws::Validate(msg));
  EXPECT_EQ(msg.utime, 42);
  EXPECT_EQ(msg.left.name, "left");
  EXPECT_EQ(msg.right.name, "right");
  const ws::Rig back = ws::RigFromMessage(msg);
  EXPECT_EQ(TableFields(back.left), TableFields(rig.left));
  EXPECT_EQ(TableFields(back.right), TableFields(rig.right));
  EXPECT_EQ(TableFields(rig.left).size(), 17u);  // the field and the tilt carried too
  EXPECT_EQ(back.R, rig.R);
  EXPECT_EQ(back.T, rig.T);
  EXPECT_EQ(back.left_rms, rig.left_rms);
  EXPECT_EQ(back.right_rms, rig.right_rms);
  EXPECT_EQ(back.rms, rig.rms);
}

}  // namespace
