#include <gtest/gtest.h>

#include "lcm_io/image_codec.h"

TEST(ImageCodec, GrayRoundTrip) {
  cv::Mat m(4, 5, CV_8UC1);
  cv::randu(m, 0, 255);
  auto msg = ws::MatToImage(m, 7);
  EXPECT_EQ(cv::norm(ws::ImageToMat(msg), m, cv::NORM_INF), 0);
}
