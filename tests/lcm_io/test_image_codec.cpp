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

namespace {

// A JPEG's start (SOI), one APP0 segment, then a baseline frame header
// (SOF0) saying width x height, then the first bytes of a scan.
std::vector<uint8_t> JpegHeader(int width, int height) {
  std::vector<uint8_t> jpeg = {0xff, 0xd8,                                  // SOI
                               0xff, 0xe0, 0, 6, 'J', 'F', 'I', 'F',        // APP0, length 6
                               0xff, 0xc0, 0, 11, 8,                        // SOF0, length 11, 8 bits
                               uint8_t(height >> 8), uint8_t(height), uint8_t(width >> 8), uint8_t(width),
                               1, 1, 0x11, 0,                               // one component
                               0xff, 0xda, 0, 8, 1, 1, 0, 0, 63, 0};        // SOS
  return jpeg;
}

std::optional<ws::PixelSize> SizeOf(const std::vector<uint8_t>& bytes) {
  return ws::CompressedImageSize(bytes.data(), bytes.size());
}

widestereo::image_t JpegMessage(std::vector<uint8_t> payload, int width, int height) {
  widestereo::image_t msg;
  msg.width = width;
  msg.height = height;
  msg.row_stride = 0;
  msg.pixelformat = widestereo::image_t::PIXEL_FORMAT_MJPEG;
  msg.data = std::move(payload);
  msg.size = int32_t(msg.data.size());
  return msg;
}

std::string DecodeErrorOf(const widestereo::image_t& msg, int64_t max_pixels = ws::kDefaultMaxImagePixels) {
  try {
    ws::ImageToMat(msg, max_pixels);
  } catch (const ws::DecodeError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(CompressedImageSize, ReadsTheJpegFrameHeaderPastOtherSegments) {
  const auto size = SizeOf(JpegHeader(16384, 16384));
  ASSERT_TRUE(size.has_value());
  EXPECT_EQ(size->width, 16384);
  EXPECT_EQ(size->height, 16384);
}

TEST(CompressedImageSize, RefusesJpegSegmentsCutShortOrRunningPastTheEnd) {
  const std::vector<uint8_t> whole = JpegHeader(640, 480);
  const size_t sof_end = 2 + 8 + 13;  // SOI, APP0, SOF0
  for (size_t cut = 0; cut < sof_end; ++cut)
    EXPECT_FALSE(SizeOf(std::vector<uint8_t>(whole.begin(), whole.begin() + long(cut))).has_value()) << cut;
  EXPECT_TRUE(SizeOf(std::vector<uint8_t>(whole.begin(), whole.begin() + long(sof_end))).has_value());

  std::vector<uint8_t> past_end = whole;
  past_end[4] = 0xff;  // APP0's length: 65280 bytes, past the end
  EXPECT_FALSE(SizeOf(past_end).has_value());
  std::vector<uint8_t> too_short = whole;
  too_short[5] = 1;  // a length below its own two bytes
  too_short[4] = 0;
  EXPECT_FALSE(SizeOf(too_short).has_value());
  std::vector<uint8_t> small_sof = whole;
  small_sof[13] = 7;  // SOF0 of 7 bytes cannot hold P, Y, X, Nf
  EXPECT_FALSE(SizeOf(small_sof).has_value());
  const std::vector<uint8_t> end_first = {0xff, 0xd8, 0xff, 0xd9, 0, 0, 0, 0};  // EOI before any frame
  EXPECT_FALSE(SizeOf(end_first).has_value());
  const std::vector<uint8_t> not_a_marker = {0xff, 0xd8, 0x12, 0x34, 0, 0, 0, 0};
  EXPECT_FALSE(SizeOf(not_a_marker).has_value());
}

TEST(CompressedImageSize, ReadsAPngIhdrAndRefusesOneCutOrMislabelled) {
  const cv::Mat image(30, 40, CV_8UC1, cv::Scalar(1));
  const widestereo::image_t msg = ws::MatToImage(image, 1, ws::Compression::png);
  const auto size = SizeOf(msg.data);
  ASSERT_TRUE(size.has_value());
  EXPECT_EQ(size->width, 40);
  EXPECT_EQ(size->height, 30);
  const size_t ihdr_end = 8 + 4 + 4 + 13;
  EXPECT_FALSE(SizeOf(std::vector<uint8_t>(msg.data.begin(), msg.data.begin() + long(ihdr_end - 1))).has_value());
  EXPECT_TRUE(SizeOf(std::vector<uint8_t>(msg.data.begin(), msg.data.begin() + long(ihdr_end))).has_value());
  std::vector<uint8_t> long_ihdr = msg.data;
  long_ihdr[11] = 14;  // IHDR's length is 13
  EXPECT_FALSE(SizeOf(long_ihdr).has_value());
  std::vector<uint8_t> other_chunk = msg.data;
  other_chunk[12] = 'X';
  EXPECT_FALSE(SizeOf(other_chunk).has_value());
}

// The frame: 1.1 KB of JPEG whose frame header says 16384 x 16384,
// cut short or with its end-of-image marker; decoding it took 510 MB.
TEST(ImageCodec, AHugeJpegIsRefusedBeforeDecodingAboveTheMaximum) {
  std::vector<uint8_t> payload = JpegHeader(16384, 16384);
  payload.resize(1100, 0x55);
  for (const bool with_end : {false, true}) {
    std::vector<uint8_t> bytes = payload;
    if (with_end) bytes.insert(bytes.end(), {0xff, 0xd9});
    const widestereo::image_t msg = JpegMessage(bytes, 16384, 16384);
    EXPECT_NO_THROW(ws::ValidateImage(msg));  // consistent, and within what any message may be
    EXPECT_NE(DecodeErrorOf(msg).find("a 16384x16384 image is 268435456 pixels, more than --max-image-pixels " +
                                      std::to_string(ws::kDefaultMaxImagePixels)),
              std::string::npos)
        << DecodeErrorOf(msg);
    EXPECT_NE(DecodeErrorOf(JpegMessage(bytes, 640, 480)).find("compressed payload is 16384x16384, header says 640x480"),
              std::string::npos);
  }
  const cv::Mat raw(20, 30, CV_8UC1, cv::Scalar(3));
  const widestereo::image_t small = ws::MatToImage(raw, 1);
  EXPECT_NE(DecodeErrorOf(small, 599).find("a 30x20 image is 600 pixels, more than --max-image-pixels 599"),
            std::string::npos);
  EXPECT_EQ(ws::ImageToMat(small, 600).size(), raw.size());
}
