// Every message type survives encode/decode, and DecodeMessage rejects what
// does not decode or validate.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include "lcm_io/decode.h"
#include "lcm_io/point_cloud.h"
#include "test_support.h"

namespace {

using namespace widestereo;

template <class Msg>
std::vector<uint8_t> Encode(const Msg& msg) {
  return ws::test::Event("X", msg).data;
}

template <class Msg>
void ExpectRoundTrip(const Msg& msg) {
  const auto bytes = Encode(msg);
  const Msg decoded = ws::DecodeMessage<Msg>(bytes.data(), int(bytes.size()));
  EXPECT_EQ(Encode(decoded), bytes) << Msg::getTypeName();
}

image_t Gray(int w, int h, uint8_t value) {
  return ws::MatToImage(cv::Mat(h, w, CV_8UC1, cv::Scalar(value)), 42);
}

camera_corners_t Corners() {
  camera_corners_t c{};
  c.board_id = "chessboard:9x6:0.025";
  c.image_width = 640;
  c.image_height = 480;
  c.n = 2;
  c.ids = {0, 1};
  c.image_points = {{10.5, 20.25}, {30.0, 40.0}};
  c.object_points = {{0, 0, 0}, {0.025, 0, 0}};
  return c;
}

camera_calibration_t Calibration(const std::string& name) {
  camera_calibration_t c{};
  c.name = name;
  c.image_width = 1280;
  c.image_height = 960;
  c.model = "bspline";
  c.degree = 3;
  c.knots = {0, 0, 0, 0, 1, 2, 2, 2, 2};
  c.nknots = int32_t(c.knots.size());
  c.coeffs = {0, 0, 0.01, 0.02, -0.01};
  c.ncoeffs = int32_t(c.coeffs.size());
  c.fx = c.fy = 346.7;
  c.cx = 640;
  c.cy = 480;
  c.p1 = 1e-4;
  c.p2 = -1e-4;
  c.rms = 0.1;
  c.view_rms = {0.1, 0.12};
  c.nviews = 2;
  c.param_names = {"fx", "fy"};
  c.stddev = {0.01, 0.02};
  c.nparams = 2;
  return c;
}

TEST(Messages, EveryTypeRoundTrips) {
  stereo_frame_t frame{};
  frame.utime = 1;
  frame.frame_id = 7;
  frame.left = Gray(4, 3, 1);
  frame.right = Gray(4, 3, 2);
  frame.left.nmetadata = 1;
  frame.left.metadata.resize(1);
  frame.left.metadata[0].key = "exposure_us";
  frame.left.metadata[0].n = 2;
  frame.left.metadata[0].value = {1, 2};
  ExpectRoundTrip(frame);
  ExpectRoundTrip(frame.left);

  stereo_corners_t corners{};
  corners.utime = 2;
  corners.frame_id = 7;
  corners.left = Corners();
  corners.right = Corners();
  ExpectRoundTrip(corners);

  stereo_calibration_t calib{};
  calib.utime = 3;
  calib.left = Calibration("left");
  calib.right = Calibration("right");
  for (int i = 0; i < 9; ++i) calib.R[i] = i % 4 == 0;
  calib.T[0] = -0.3;
  calib.rms = 0.2;
  calib.nviews = 1;
  calib.view_rms = {0.2};
  ExpectRoundTrip(calib);

  calibration_status_t status{};
  status.utime = 4;
  status.state = "collecting";
  status.grid_rows = 2;
  status.grid_cols = 3;
  status.coverage_left = {{1, 2, 3}, {4, 5, 6}};
  status.coverage_right = {{0, 0, 0}, {1, 1, 1}};
  status.rms = -1;
  status.hint = "move the board to the top-left corner";
  ExpectRoundTrip(status);

  disparity_t disparity{};
  disparity.utime = 5;
  disparity.disparity = ws::MatToImage(cv::Mat(3, 4, CV_32FC1, cv::Scalar(1.5f)), 5);
  disparity.min_disparity = 0;
  disparity.num_disparities = 64;
  disparity.Q[15] = 1;
  disparity.rectification = disparity_t::RECTIFICATION_LATLON;
  disparity.f = 300;
  disparity.cx = 1.5;
  disparity.cy = 1;
  disparity.baseline = 0.15;
  ExpectRoundTrip(disparity);

  point_cloud_t cloud{};
  cloud.utime = 6;
  cloud.frame = "left_rectified";
  cloud.npoints = 2;
  cloud.xyz = {{0, 0, 2}, {0.1f, 0.2f, 2.1f}};
  cloud.nintensity = 2;
  cloud.intensity = {10, 20};
  ExpectRoundTrip(cloud);

  cloud_stats_t stats{};
  stats.utime = 7;
  stats.plane_found = true;
  stats.plane_normal[2] = 1;
  stats.plane_offset = -2;
  stats.nstages = 2;
  stats.stage_names = {"input", "voxel"};
  stats.stage_points = {100, 50};
  stats.stage_ms = {0.1, 2.5};
  ExpectRoundTrip(stats);

  process_status_t ps{};
  ps.utime = 8;
  ps.name = "stereo-detect";
  ps.host = "robot";
  ps.pid = 123;
  ps.nchannels = 1;
  ps.channels.resize(1);
  ps.channels[0].channel = "STEREO_IMAGES";
  ps.channels[0].received = 10;
  ps.channels[0].dropped = 1;
  ps.nstages = 1;
  ps.stages = {{"match", 10, 10, 30.5f, 41.f}};
  ExpectRoundTrip(ps);

  command_t command{};
  command.utime = 9;
  command.command = "solve";
  command.nargs = 1;
  command.args = {"model=bspline"};
  ExpectRoundTrip(command);
}

TEST(Messages, ImageOfEveryFormatRoundTripsThroughMat) {
  cv::Mat gray(5, 7, CV_8UC1), gray16(5, 7, CV_16UC1), bgr(5, 7, CV_8UC3), f32(5, 7, CV_32FC1);
  cv::randu(gray, 0, 255);
  cv::randu(gray16, 0, 65535);
  cv::randu(bgr, 0, 255);
  cv::randu(f32, -10, 10);
  for (const cv::Mat& m : {gray, gray16, bgr, f32})
    EXPECT_EQ(cv::norm(ws::ImageToMat(ws::MatToImage(m, 1)), m, cv::NORM_INF), 0) << m.type();
  for (const cv::Mat& m : {gray, gray16, bgr})
    EXPECT_EQ(cv::norm(ws::ImageToMat(ws::MatToImage(m, 1, ws::Compression::png)), m,
                       cv::NORM_INF), 0) << m.type();
  const cv::Mat jpeg = ws::ImageToMat(ws::MatToImage(bgr, 1, ws::Compression::jpeg, 100));
  EXPECT_EQ(jpeg.size(), bgr.size());
  EXPECT_EQ(jpeg.type(), CV_8UC3);
}

TEST(Messages, RgbPayloadComesOutInBgrOrder) {
  image_t msg = Gray(1, 1, 0);
  msg.pixelformat = image_t::PIXEL_FORMAT_RGB;
  msg.row_stride = 3;
  msg.data = {10, 20, 30};
  msg.size = 3;
  const cv::Mat m = ws::ImageToMat(msg);
  EXPECT_EQ(m.at<cv::Vec3b>(0, 0), cv::Vec3b(30, 20, 10));
}

TEST(Messages, ImageWhoseSizesDisagreeIsRejected) {
  image_t msg = Gray(4, 3, 0);
  msg.height = 4;  // height x row_stride = 16 but 12 bytes of payload
  EXPECT_THROW(ws::ImageToMat(msg), ws::DecodeError);
  msg = Gray(4, 3, 0);
  msg.row_stride = 3;  // shorter than a row
  EXPECT_THROW(ws::ImageToMat(msg), ws::DecodeError);
  msg = Gray(4, 3, 0);
  msg.width = -4;
  EXPECT_THROW(ws::ImageToMat(msg), ws::DecodeError);
  msg = Gray(4, 3, 0);
  msg.pixelformat = 12345;
  EXPECT_THROW(ws::ImageToMat(msg), ws::DecodeError);
  // Through the wire: a stereo frame carrying such an image.
  stereo_frame_t frame{};
  frame.left = Gray(4, 3, 0);
  frame.right = Gray(4, 3, 0);
  frame.right.height = 30;
  const auto bytes = Encode(frame);
  EXPECT_THROW(ws::DecodeMessage<stereo_frame_t>(bytes.data(), int(bytes.size())), ws::DecodeError);
}

TEST(Messages, CompressedPayloadMustDecodeToTheAnnouncedSize) {
  image_t msg = ws::MatToImage(cv::Mat(8, 8, CV_8UC1, cv::Scalar(9)), 1, ws::Compression::jpeg);
  image_t truncated = msg;
  truncated.data.resize(truncated.data.size() / 3);
  truncated.size = int32_t(truncated.data.size());
  EXPECT_THROW(ws::ImageToMat(truncated), ws::DecodeError);
  image_t wrong_size = msg;
  wrong_size.width = 9;
  EXPECT_THROW(ws::ImageToMat(wrong_size), ws::DecodeError);
}

TEST(Messages, WrongTypeTruncatedAndTrailingBytesAreRejected) {
  command_t command{};
  command.command = "solve";
  command.nargs = 0;
  auto bytes = Encode(command);
  EXPECT_THROW(ws::DecodeMessage<stereo_frame_t>(bytes.data(), int(bytes.size())), ws::DecodeError);
  EXPECT_THROW(ws::DecodeMessage<command_t>(bytes.data(), int(bytes.size()) - 1), ws::DecodeError);
  bytes.push_back(0);
  EXPECT_THROW(ws::DecodeMessage<command_t>(bytes.data(), int(bytes.size())), ws::DecodeError);
}

TEST(Messages, NegativeOrHugeArrayLengthsAreRejected) {
  point_cloud_t cloud{};
  cloud.npoints = 0;
  cloud.nintensity = 0;
  auto bytes = Encode(cloud);
  // npoints sits after hash (8), utime (8), frame_id (8), frame (4 + 1 bytes).
  const size_t npoints_at = 8 + 8 + 8 + 5;
  for (uint8_t first_byte : {uint8_t(0xff), uint8_t(0x7f)}) {
    auto bad = bytes;
    bad[npoints_at] = first_byte;  // -16777216 or 2^31-ish points in a 40-byte message
    EXPECT_THROW(ws::DecodeMessage<point_cloud_t>(bad.data(), int(bad.size())), ws::DecodeError);
  }
}

// The first `points` of three points (an odd one among them), with
// intensity, in either cloud type.
template <class Cloud>
Cloud SampleCloud(int points) {
  const float xyz[3][3] = {{0, 0, 2}, {0.1f, -0.2f, 2.1f}, {1e-30f, 3e30f, -0.f}}, intensity[3] = {10, 20, 255};
  Cloud cloud{};
  cloud.utime = 6;
  cloud.frame_id = 9;
  cloud.frame = "left_rectified";
  for (int i = 0; i < points; ++i) {
    cloud.xyz.push_back({xyz[i][0], xyz[i][1], xyz[i][2]});
    cloud.intensity.push_back(intensity[i]);
  }
  cloud.npoints = cloud.nintensity = points;
  return cloud;
}

// stereo-match and stereo-cloud send and take their clouds as ws::PointCloud
// (its points in one array): the bytes of point_cloud_t, both ways, and the
// same refusals.
TEST(Messages, PointCloudIsPointCloudTOnTheWire) {
  auto flat = SampleCloud<ws::PointCloud>(3);
  const auto bytes = Encode(SampleCloud<point_cloud_t>(3));
  EXPECT_EQ(Encode(flat), bytes);
  EXPECT_EQ(flat.getEncodedSize(), int(bytes.size()));
  const auto decoded = ws::DecodeMessage<ws::PointCloud>(bytes.data(), int(bytes.size()));
  EXPECT_EQ(Encode(decoded), bytes);
  EXPECT_EQ(decoded.xyz, flat.xyz);
  EXPECT_EQ(decoded.frame, "left_rectified");
  EXPECT_EQ(Encode(SampleCloud<ws::PointCloud>(0)), Encode(SampleCloud<point_cloud_t>(0))) << "no points";
  flat.npoints = 4;
  EXPECT_LT(flat.encode(std::vector<uint8_t>(1024).data(), 0, 1024), 0) << "npoints beyond its points";

  // Every truncation, and every length field made negative or too long.
  for (size_t size = 0; size < bytes.size(); ++size)
    EXPECT_THROW(ws::DecodeMessage<ws::PointCloud>(bytes.data(), int(size)), ws::DecodeError) << size;
  const size_t frame_at = 8 + 8 + 8, npoints_at = frame_at + 4 + 15, nintensity_at = npoints_at + 4 + 3 * 12;
  for (size_t at : {frame_at, npoints_at, nintensity_at})
    for (uint8_t first_byte : {uint8_t(0xff), uint8_t(0x7f)}) {
      auto bad = bytes;
      bad[at] = first_byte;
      EXPECT_THROW(ws::DecodeMessage<point_cloud_t>(bad.data(), int(bad.size())), ws::DecodeError) << at;
      EXPECT_THROW(ws::DecodeMessage<ws::PointCloud>(bad.data(), int(bad.size())), ws::DecodeError) << at;
    }
  auto nul = bytes;
  nul[frame_at + 4 + 3] = 0;  // "lef\0_rectified"
  EXPECT_THROW(ws::DecodeMessage<point_cloud_t>(nul.data(), int(nul.size())), ws::DecodeError);
  EXPECT_THROW(ws::DecodeMessage<ws::PointCloud>(nul.data(), int(nul.size())), ws::DecodeError);
  auto one_intensity = bytes;  // nintensity 1 of 3 points: decodes, does not validate
  one_intensity[nintensity_at + 3] = 1;
  one_intensity.resize(nintensity_at + 4 + 4);
  EXPECT_THROW(ws::DecodeMessage<ws::PointCloud>(one_intensity.data(), int(one_intensity.size())), ws::DecodeError);
}

// Found by tests/fuzz: LCM's string decoder took any length field and any
// bytes; a NUL inside a string made the message re-encode shorter than it
// said, and INT32_MIN overflowed. A string is its bytes and one NUL.
TEST(Messages, StringsAreTheirBytesAndOneNul) {
  command_t command{};
  command.command = "solve";
  command.nargs = 0;
  const auto bytes = Encode(command);
  const size_t length_at = 8 + 8, text_at = length_at + 4;  // after the hash and utime
  ASSERT_EQ(bytes[length_at + 3], 6);                       // "solve" and its NUL
  auto decodes = [](const std::vector<uint8_t>& b) {
    try {
      ws::DecodeMessage<command_t>(b.data(), int(b.size()));
      return true;
    } catch (const ws::DecodeError&) {
      return false;
    }
  };
  EXPECT_TRUE(decodes(bytes));
  auto inner_nul = bytes;
  inner_nul[text_at + 2] = 0;  // "so" NUL "ve" NUL
  EXPECT_FALSE(decodes(inner_nul));
  auto no_nul = bytes;
  no_nul[text_at + 5] = 'x';  // "solvex" without its NUL
  EXPECT_FALSE(decodes(no_nul));
  for (const uint8_t first : {uint8_t(0x80), uint8_t(0xff)}) {  // INT32_MIN, -250
    auto negative = bytes;
    negative[length_at] = first;
    EXPECT_FALSE(decodes(negative));
  }
  auto zero = bytes;
  zero[length_at + 3] = 0;
  EXPECT_FALSE(decodes(zero));
}

TEST(Messages, StageTimesAreChecked) {
  process_status_t ps{};
  ps.stages = {{"match", 10, 10, 30.5f, 41.f}};
  ps.nstages = 1;
  EXPECT_NO_THROW(ws::Validate(ps));
  for (auto broken : {widestereo::stage_time_t{"match", 10, 11, 30.5f, 41.f},  // window beyond count
                      widestereo::stage_time_t{"match", 10, 10, 50.f, 41.f},   // median above p99
                      widestereo::stage_time_t{"match", 10, 10, -1.f, 41.f},
                      widestereo::stage_time_t{"match", 10, 10, 30.5f, std::numeric_limits<float>::infinity()}}) {
    ps.stages = {broken};
    EXPECT_THROW(ws::Validate(ps), ws::DecodeError) << broken.median_ms << " " << broken.p99_ms;
  }
}

TEST(Messages, CornersAndCalibrationsAreChecked) {
  camera_corners_t corners = Corners();
  corners.image_points[1][0] = std::nan("");
  EXPECT_THROW(ws::Validate(corners), ws::DecodeError);
  EXPECT_NO_THROW(ws::Validate(Corners()));
  corners = Corners();
  corners.ids = {1, 1};  // tests/fuzz: a view with a repeated id was never a near duplicate of itself
  EXPECT_THROW(ws::Validate(corners), ws::DecodeError);
  // No more points than the board named has corners, every id on it.
  corners = Corners();
  corners.ids = {0, 54};
  EXPECT_THROW(ws::Validate(corners), ws::DecodeError);
  corners = Corners();
  corners.board_id = "babelcalib:ov_plane.dsc";  // another tool's board: bounded all the same
  EXPECT_NO_THROW(ws::Validate(corners));
  corners.ids = {0, 10000};
  EXPECT_THROW(ws::Validate(corners), ws::DecodeError);
  corners = Corners();
  corners.n = 55;
  corners.ids.resize(55);
  for (int i = 0; i < 55; ++i) corners.ids[size_t(i)] = i;
  corners.image_points.assign(55, {1.0, 1.0});
  corners.object_points.assign(55, {0.0, 0.0, 0.0});
  try {
    ws::Validate(corners);
    ADD_FAILURE() << "a flood of points passed";
  } catch (const ws::DecodeError& e) {
    EXPECT_NE(std::string(e.what()).find("55 corners on a board of 54"), std::string::npos) << e.what();
  }
  camera_calibration_t calib = Calibration("left");
  calib.model = "fisheye9000";
  EXPECT_THROW(ws::Validate(calib), ws::DecodeError);
  calib = Calibration("left");
  calib.coeffs.push_back(0);
  calib.ncoeffs++;
  EXPECT_THROW(ws::Validate(calib), ws::DecodeError);
  EXPECT_NO_THROW(ws::Validate(Calibration("left")));
  // Every kind of the model table, the fisheye ones too.
  calib = Calibration("left");
  calib.model = "bspline_theta";
  EXPECT_NO_THROW(ws::Validate(calib));
  calib.model = "kb4";
  calib.degree = calib.nknots = calib.p1 = calib.p2 = 0;
  calib.knots.clear();
  calib.coeffs = {0.01, -0.002, 0.0, 0.0};
  calib.ncoeffs = 4;
  EXPECT_NO_THROW(ws::Validate(calib));
  // A non-radial field: its grid's number of coefficients, finite and small.
  calib = Calibration("left");
  calib.field_cols = calib.field_rows = 4;
  calib.field_domain[0] = calib.field_domain[2] = -2;
  calib.field_domain[1] = calib.field_domain[3] = 2;
  calib.field_coeffs.assign(32, 1e-3);
  calib.nfield = 32;
  calib.sensor_tilt[0] = 0.01;  // a sensor tilt: finite and below kMaxSensorTilt
  calib.sensor_tilt[1] = -0.02;
  EXPECT_NO_THROW(ws::Validate(calib));
  for (auto bad : {+[](camera_calibration_t& c) { c.field_rows = 3; },
                   +[](camera_calibration_t& c) { c.sensor_tilt[0] = 0.5; },
                   +[](camera_calibration_t& c) { c.sensor_tilt[1] = std::nan(""); },
                   +[](camera_calibration_t& c) { c.field_coeffs.pop_back(), --c.nfield; },
                   +[](camera_calibration_t& c) { c.field_coeffs[5] = 2; },
                   +[](camera_calibration_t& c) { c.field_domain[1] = -2; },
                   +[](camera_calibration_t& c) { c.field_domain[3] = std::nan(""); }}) {
    camera_calibration_t broken = calib;
    bad(broken);
    EXPECT_THROW(ws::Validate(broken), ws::DecodeError);
  }
}

// Found by the fault-injection test: stereo-match spent minutes building
// rectification maps for a calibration of a 1048576-pixel-wide camera; and by
// tests/fuzz: a 1e270 px focal length.
TEST(Messages, CalibrationsLargerThanAnyImageOrWithoutARotationAreRejected) {
  camera_calibration_t calib = Calibration("left");
  calib.image_width = 1 << 20;
  EXPECT_THROW(ws::Validate(calib), ws::DecodeError);
  calib.image_width = 1 << 16;
  calib.image_height = 1 << 13;  // each side within the limit, 2^29 pixels in all
  EXPECT_THROW(ws::Validate(calib), ws::DecodeError);

  // Intrinsics no camera has: the model's arithmetic loses every digit.
  for (auto bad : {+[](camera_calibration_t& c) { c.fx = 1e270; },
                   +[](camera_calibration_t& c) { c.fy = 0; },
                   +[](camera_calibration_t& c) { c.cx = -2000; },  // the image is 1280 wide
                   +[](camera_calibration_t& c) { c.cy = 3000; },   // and 960 high
                   +[](camera_calibration_t& c) { c.p2 = 2; }}) {
    calib = Calibration("left");
    bad(calib);
    EXPECT_THROW(ws::Validate(calib), ws::DecodeError);
  }

  stereo_calibration_t stereo{};
  stereo.left = stereo.right = Calibration("left");
  const double turn[9] = {0, -1, 0, 1, 0, 0, 0, 0, 1};  // 90 degrees about z
  std::copy(turn, turn + 9, stereo.R);
  EXPECT_NO_THROW(ws::Validate(stereo));
  stereo.R[0] = 0.5;  // rows no longer orthonormal
  EXPECT_THROW(ws::Validate(stereo), ws::DecodeError);
  const double mirror[9] = {-1, 0, 0, 0, 1, 0, 0, 0, 1};  // orthonormal, det -1
  std::copy(mirror, mirror + 9, stereo.R);
  EXPECT_THROW(ws::Validate(stereo), ws::DecodeError);
}

}  // namespace

namespace {

// libbot's bot_core.image_metadata_t fingerprint base (its generated code);
// LCM hashes field names and types, not the package, so ours must equal it
// for bot_core viewers to decode our images.
TEST(Messages, ImageLayoutIsLibbotsBotCoreImage) {
  const uint64_t bot_core_metadata_base = 0x4d25b1a682bbfdc7ULL;
  const uint64_t rotated = (bot_core_metadata_base << 1) + (bot_core_metadata_base >> 63);
  EXPECT_EQ(uint64_t(widestereo::image_metadata_t::getHash()), rotated);
}

}  // namespace
