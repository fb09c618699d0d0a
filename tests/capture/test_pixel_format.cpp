#include <cstdint>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include "capture/camera_error.h"
#include "capture/pixel_format.h"

namespace {

cv::Mat RandomImage(int type, cv::Size size = {7, 5}) {
  cv::Mat image(size, type);
  cv::randu(image, 0, CV_MAT_DEPTH(type) == CV_16U ? 65535 : 255);
  return image;
}

// Serves `image` in `format` and reads it back.
cv::Mat RoundTrip(const cv::Mat& image, const std::string& format) {
  const uint32_t code = ws::PixelFormatCode(format);
  std::vector<uint8_t> pixels(image.total() * ws::BytesPerPixel(code));
  ws::MatToPixels(image, code, image.cols, image.rows, pixels.data());
  return ws::PixelsToMat(pixels.data(), pixels.size(), image.cols, image.rows,
                         image.cols * ws::BytesPerPixel(code), code);
}

TEST(PixelFormat, NamesAndCodes) {
  EXPECT_EQ(ws::SupportedPixelFormats(),
            (std::vector<std::string>{"Mono8", "Mono16", "RGB8", "BGR8"}));
  EXPECT_EQ(ws::PixelFormatCode("Mono8"), 0x01080001u);
  EXPECT_EQ(ws::PixelFormatName(0x02180014u), "RGB8");
  EXPECT_EQ(ws::PixelFormatName(0x01080008u), "0x01080008");  // BayerBG8
  EXPECT_EQ(ws::BytesPerPixel(ws::PixelFormatCode("Mono16")), 2u);
  EXPECT_THROW(ws::PixelFormatCode("Mono12"), ws::CameraError);
  EXPECT_THROW(ws::BytesPerPixel(0x01080008u), ws::CameraError);
}

TEST(PixelFormat, EachFormatRoundTripsExactly) {
  const cv::Mat mono8 = RandomImage(CV_8UC1);
  const cv::Mat mono16 = RandomImage(CV_16UC1);
  const cv::Mat color = RandomImage(CV_8UC3);
  EXPECT_EQ(cv::norm(RoundTrip(mono8, "Mono8"), mono8, cv::NORM_INF), 0);
  EXPECT_EQ(cv::norm(RoundTrip(mono16, "Mono16"), mono16, cv::NORM_INF), 0);
  EXPECT_EQ(cv::norm(RoundTrip(color, "RGB8"), color, cv::NORM_INF), 0);
  EXPECT_EQ(cv::norm(RoundTrip(color, "BGR8"), color, cv::NORM_INF), 0);
  EXPECT_EQ(RoundTrip(mono16, "Mono16").type(), CV_16UC1);
  EXPECT_EQ(RoundTrip(color, "RGB8").type(), CV_8UC3);
}

TEST(PixelFormat, Rgb8IsSentInRgbOrder) {
  const cv::Mat blue(1, 1, CV_8UC3, cv::Scalar(255, 0, 0));  // BGR
  uint8_t pixel[3];
  ws::MatToPixels(blue, ws::PixelFormatCode("RGB8"), 1, 1, pixel);
  EXPECT_EQ(pixel[0], 0);
  EXPECT_EQ(pixel[2], 255);
}

TEST(PixelFormat, ServingConvertsChannelsDepthAndSize) {
  const cv::Mat gray(4, 6, CV_8UC1, cv::Scalar(100));
  std::vector<uint16_t> wide(12 * 8);
  ws::MatToPixels(gray, ws::PixelFormatCode("Mono16"), 12, 8, wide.data());
  EXPECT_EQ(wide.front(), 100 * 257);
  EXPECT_EQ(wide.back(), 100 * 257);

  std::vector<uint8_t> rgb(6 * 4 * 3);
  ws::MatToPixels(gray, ws::PixelFormatCode("RGB8"), 6, 4, rgb.data());
  EXPECT_EQ(rgb[0], 100);
  EXPECT_EQ(rgb[2], 100);

  const cv::Mat color(4, 6, CV_16UC3, cv::Scalar(257 * 10, 257 * 10, 257 * 10));
  std::vector<uint8_t> mono(6 * 4, 1);
  ws::MatToPixels(color, ws::PixelFormatCode("Mono8"), 6, 4, mono.data());
  EXPECT_EQ(mono[5], 10);

  ws::MatToPixels(cv::Mat(), ws::PixelFormatCode("Mono8"), 6, 4, mono.data());
  EXPECT_EQ(mono[7], 0);  // an empty image is served black
  EXPECT_THROW(
      ws::MatToPixels(cv::Mat(2, 2, CV_32FC1), ws::PixelFormatCode("Mono8"), 2, 2, mono.data()),
      ws::CameraError);
}

TEST(PixelFormat, ReadingHonoursRowPaddingAndChecksSize) {
  // Two rows of 3 pixels, each row padded to 5 bytes.
  const uint8_t padded[] = {1, 2, 3, 0, 0, 4, 5, 6, 0, 0};
  const cv::Mat image =
      ws::PixelsToMat(padded, sizeof padded, 3, 2, 5, ws::PixelFormatCode("Mono8"));
  EXPECT_EQ(image.at<uint8_t>(1, 0), 4);
  EXPECT_TRUE(image.isContinuous());
  EXPECT_THROW(ws::PixelsToMat(padded, 7, 3, 2, 5, ws::PixelFormatCode("Mono8")), ws::CameraError);
  EXPECT_THROW(ws::PixelsToMat(padded, sizeof padded, 3, 2, 2, ws::PixelFormatCode("Mono8")),
               ws::CameraError);
}

}  // namespace
