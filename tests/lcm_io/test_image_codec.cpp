#include <gtest/gtest.h>

#include "lcm_io/compressed_size.h"
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

// Found by tests/fuzz: a few hundred bytes of JPEG claiming a large image
// took a second to decode. Its own header is read first, and the payload is
// refused unless it says the message's size.
TEST(ImageCodec, CompressedPayloadOfAnotherSizeIsRefusedBeforeDecoding) {
  for (const auto compression : {ws::Compression::jpeg, ws::Compression::png}) {
    const cv::Mat big(3000, 4000, CV_8UC1, cv::Scalar(7));
    widestereo::image_t msg = ws::MatToImage(big, 1, compression);
    const auto size = ws::CompressedImageSize(msg.data.data(), msg.data.size());
    ASSERT_TRUE(size.has_value());
    EXPECT_EQ(size->width, 4000);
    EXPECT_EQ(size->height, 3000);
    EXPECT_EQ(ws::ImageToMat(msg).size(), big.size());
    msg.width = 32;  // the message claims a small image
    msg.height = 24;
    msg.row_stride = 32;
    try {
      ws::ImageToMat(msg);
      ADD_FAILURE() << "decoded a payload of another size";
    } catch (const ws::DecodeError& e) {
      EXPECT_NE(std::string(e.what()).find("compressed payload is 4000x3000, header says 32x24"), std::string::npos)
          << e.what();
    }
  }
  const std::vector<uint8_t> not_an_image = {0xff, 0xd8, 0xff, 0xda, 0, 8, 1, 2, 3, 4};  // a scan, no frame header
  EXPECT_FALSE(ws::CompressedImageSize(not_an_image.data(), not_an_image.size()).has_value());
}
