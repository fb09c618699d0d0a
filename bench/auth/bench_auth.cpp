// What the rig key costs per message (docs/security.md): for a command, a
// calibration, a corners message and an image pair as the processes send
// them, the time to encode the message (what every publish pays) and to
// decode and validate it (what every receiver pays), the baselines, beside
// the time to encode it signed (auth::EncodeSigned: the encoding, keyed
// BLAKE2b-256) and to decode and check it (auth::AuthCheck::Check on the
// bytes as received: the MAC, the nonce), in microseconds per message and
// as multiples of the baselines, all measured in the same run.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

#include <CLI/CLI.hpp>
#include <sodium.h>

#include "auth/message_auth.h"
#include "lcm_io/decode.h"
#include "lcm_io/channels.h"
#include "lcm_io/image_codec.h"
#include "rectify/stereo_rig.h"
#include "runtime/wall_clock.h"
#include "widestereo/command_t.hpp"
#include "widestereo/stereo_corners_t.hpp"
#include "widestereo/stereo_frame_t.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double MicrosPer(Clock::time_point start, int count) {
  return std::chrono::duration<double, std::micro>(Clock::now() - start).count() / count;
}

// A whole board of cols x rows inner corners as stereo-detect sends it.
widestereo::camera_corners_t BoardCorners(int cols, int rows, double spacing) {
  widestereo::camera_corners_t c{};
  c.board_id = "chessboard:" + std::to_string(cols) + "x" + std::to_string(rows) + ":" + std::to_string(spacing);
  c.image_width = 1280;
  c.image_height = 960;
  for (int i = 0; i < cols * rows; ++i) {
    c.ids.push_back(i);
    c.image_points.push_back({100.0 + 40 * (i % cols), 100.0 + 40 * (i / cols)});
    c.object_points.push_back({spacing * (i % cols), spacing * (i / cols), 0.0});
  }
  c.n = cols * rows;
  return c;
}

template <class Msg>
void Measure(const char* what, const std::string& channel, const Msg& msg, int count) {
  const ws::auth::RigKey key = ws::auth::RigKey::FromSecret(std::string(32, 'k'));
  long checksum = 0;
  auto start = Clock::now();
  for (int i = 0; i < count; ++i) checksum += long(ws::EncodeMessage(msg).size());
  const double encode_us = MicrosPer(start, count);
  const std::vector<uint8_t> bytes = ws::EncodeMessage(msg);
  start = Clock::now();
  for (int i = 0; i < count; ++i) checksum += ws::DecodeMessage<Msg>(bytes.data(), int(bytes.size())).utime != 0;
  const double decode_us = MicrosPer(start, count);

  const int64_t now = ws::WallMicros();
  std::vector<std::vector<uint8_t>> signed_bytes;
  start = Clock::now();
  for (int i = 0; i < count; ++i) signed_bytes.push_back(ws::auth::EncodeSigned(key, channel, "bench_auth", now, msg));
  const double sign_us = MicrosPer(start, count);

  ws::auth::AuthCheck check(key);
  start = Clock::now();
  for (auto& b : signed_bytes) {
    const Msg m = ws::DecodeMessage<Msg>(b.data(), int(b.size()));
    check.Check(channel, m, b.data(), b.size(), now);
    b = {};  // an image pair's bytes go as they are checked
  }
  const double check_us = MicrosPer(start, count);

  std::printf("%-12s %8d bytes  encode %8.2f us, signed %8.2f us (%5.2f x)  decode %8.2f us, checked %8.2f us (%5.2f x)%s\n",
              what, int(bytes.size()), encode_us, sign_us, sign_us / encode_us, decode_us, check_us,
              check_us / decode_us, checksum == 0 ? " (nothing encoded?)" : "");
}

// The MAC alternative, HMAC-SHA512-256 (libsodium's crypto_auth), over the
// same encoded pair: what keyed BLAKE2b-256 was chosen against.
void MeasureHmac(const widestereo::stereo_frame_t& pair, int count) {
  const std::vector<uint8_t> bytes = ws::EncodeMessage(pair);
  const ws::auth::RigKey key = ws::auth::RigKey::FromSecret(std::string(32, 'k'));
  uint8_t mac[crypto_auth_hmacsha512256_BYTES];
  auto start = Clock::now();
  for (int i = 0; i < count; ++i) crypto_auth_hmacsha512256(mac, bytes.data(), bytes.size(), key.mac_key().data());
  const double hmac_us = MicrosPer(start, count);
  start = Clock::now();
  for (int i = 0; i < count; ++i) ws::auth::Mac(key, ws::channel::kStereoImages, bytes.data(), bytes.size());
  const double blake_us = MicrosPer(start, count);
  std::printf("image pair MAC alone: keyed BLAKE2b-256 %8.2f us, HMAC-SHA512-256 %8.2f us (%.2f x)\n", blake_us,
              hmac_us, hmac_us / blake_us);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("Cost of signing and checking a command, a calibration, a corners message and an image pair with the rig key, beside encoding and decoding them.",
               "bench_auth");
  int count = 20000;
  std::string calib = "config/calib/sim-default.yaml";
  app.add_option("--count", count, "Messages of each kind")->check(CLI::Range(1, 1000000))->capture_default_str();
  app.add_option("--calib", calib, "Calibration file whose STEREO_CALIBRATION is measured")
      ->check(CLI::ExistingFile)
      ->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  widestereo::command_t command{};
  command.command = "save";
  command.target = "stereo-cloud";
  command.args = {"path=cloud.pcd"};
  command.nargs = 1;
  widestereo::stereo_calibration_t calibration = ws::MessageFromStereoRig(ws::StereoRigFromFile(calib), 1);
  calibration.view_rms.assign(30, 0.05);  // as after a solve of 30 views
  calibration.nviews = 30;
  std::printf("%d messages of each kind\n", count);
  Measure("command", ws::channel::kStereoCommand, command, count);
  Measure("calibration", ws::channel::kStereoCalibration, calibration, count);
  widestereo::stereo_corners_t corners{};
  corners.utime = 1;
  corners.left = BoardCorners(9, 6, 0.025);
  corners.right = corners.left;
  Measure("corners", ws::channel::kStereoCorners, corners, count);
  widestereo::stereo_frame_t pair{};
  pair.utime = 1;
  pair.left = ws::MatToImage(cv::Mat(960, 1280, CV_8UC1, cv::Scalar(128)), 1);
  pair.right = pair.left;
  Measure("image pair", ws::channel::kStereoImages, pair, std::max(1, count / 100));
  MeasureHmac(pair, std::max(1, count / 100));
  return 0;
}
