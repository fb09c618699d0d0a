#include "view/freshness.h"

#include <gtest/gtest.h>

namespace {

using ws::view::Freshness;

TEST(Freshness, AChannelIsStaleOnceSilentLongerThanThreeSecondsOrThreeOfItsIntervals) {
  Freshness f;
  EXPECT_TRUE(f.Json(0).empty()) << "a channel never heard is not stale: its panel says what it waits for";
  for (int64_t t = 0; t <= 2000000; t += 100000) f.Heard("STEREO_IMAGES", t);  // 10 Hz
  auto images = f.Json(2000000 + Freshness::kStaleAfterUs)["STEREO_IMAGES"];
  EXPECT_EQ(images["source"], "stereo-capture");
  EXPECT_EQ(images["last_us"], 2000000);
  EXPECT_NEAR(images["rate_hz"].get<double>(), 10, 1e-6);
  EXPECT_FALSE(images["stale"]);
  images = f.Json(2000001 + Freshness::kStaleAfterUs)["STEREO_IMAGES"];
  EXPECT_TRUE(images["stale"]);
  EXPECT_NEAR(images["age_s"].get<double>(), 3.000001, 1e-9);

  // A slow channel (one message in 2 s) is stale after three of its intervals.
  for (int64_t t = 0; t <= 8000000; t += 2000000) f.Heard("CALIBRATION_HEALTH", t);
  EXPECT_FALSE(f.Json(8000000 + 5900000)["CALIBRATION_HEALTH"]["stale"]);
  EXPECT_TRUE(f.Json(8000000 + 6100000)["CALIBRATION_HEALTH"]["stale"]);
  EXPECT_EQ(f.Json(0)["CALIBRATION_HEALTH"]["source"], "stereo-health");
}

TEST(Freshness, OneMessageHasNoRateYet) {
  Freshness f;
  f.Heard("SOMETHING_ELSE", 5);
  const auto j = f.Json(6)["SOMETHING_ELSE"];
  EXPECT_TRUE(j["rate_hz"].is_null());
  EXPECT_EQ(j["source"], "");
}

}  // namespace
