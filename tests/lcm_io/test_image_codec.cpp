#include <gtest/gtest.h>

#include "lcm_io/image_codec.h"

TEST(ImageCodec, RawPayloadRespectsRowStride) {
  widestereo::image_t msg;
  msg.width = 2;
  msg.height = 2;
  msg.row_stride = 4;  // two bytes of padding per row
  msg.pixelformat = widestereo::image_t::PIXEL_FORMAT_GRAY;
  msg.data = {1, 2, 99, 99, 3, 4, 99, 99};
  msg.size = 8;
  const cv::Mat m = ws::ImageToMat(msg);
  EXPECT_EQ(m.at<uint8_t>(0, 1), 2);
  EXPECT_EQ(m.at<uint8_t>(1, 0), 3);
  EXPECT_TRUE(m.isContinuous());
}

TEST(ImageCodec, ParsesCompressionNames) {
  EXPECT_EQ(ws::ParseCompression("png"), ws::Compression::png);
  EXPECT_THROW(ws::ParseCompression("gif"), std::invalid_argument);
}
