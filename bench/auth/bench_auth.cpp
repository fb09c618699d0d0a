// What the rig key costs per message (docs/security.md, "Security on the robot
// network"): for a command and a calibration as the processes send them,
// the time to encode the message (what every publish pays) and to decode
// and validate it (what every receiver pays), the baselines, beside the time
// to sign it (auth::Sign: the MAC input encoded, HMAC-SHA512-256) and to
// check it (auth::AuthCheck::Check: a copy re-encoded, the HMAC, the nonce),
// in microseconds per message and as multiples of the baselines, all
// measured in the same run.
#include <chrono>
#include <cstdio>
#include <vector>

#include <CLI/CLI.hpp>

#include "auth/message_auth.h"
#include "lcm_io/decode.h"
#include "lcm_io/channels.h"
#include "rectify/stereo_rig.h"
#include "runtime/wall_clock.h"
#include "widestereo/command_t.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double MicrosPer(Clock::time_point start, int count) {
  return std::chrono::duration<double, std::micro>(Clock::now() - start).count() / count;
}

template <class Msg>
void Measure(const char* what, const std::string& channel, const Msg& msg, int count) {
  const ws::auth::RigKey key = ws::auth::RigKey::FromSecret(std::string(32, 'k'));
  std::vector<uint8_t> bytes(size_t(msg.getEncodedSize()));
  long checksum = 0;
  auto start = Clock::now();
  for (int i = 0; i < count; ++i) checksum += msg.encode(bytes.data(), 0, int(bytes.size()));
  const double encode_us = MicrosPer(start, count);
  start = Clock::now();
  for (int i = 0; i < count; ++i) checksum += ws::DecodeMessage<Msg>(bytes.data(), int(bytes.size())).utime != 0;
  const double decode_us = MicrosPer(start, count);

  std::vector<Msg> signed_msgs(size_t(count), msg);
  const int64_t now = ws::WallMicros();
  start = Clock::now();
  for (Msg& m : signed_msgs) ws::auth::Sign(key, channel, "bench_auth", now, m);
  const double sign_us = MicrosPer(start, count);

  ws::auth::AuthCheck check(key);
  start = Clock::now();
  for (const Msg& m : signed_msgs) check.Check(channel, m, now);
  const double check_us = MicrosPer(start, count);

  std::printf("%-12s %5d bytes  encode %6.2f us, sign %6.2f us (%5.1f x)  decode %6.2f us, check %6.2f us (%5.1f x)%s\n",
              what, int(bytes.size()), encode_us, sign_us, sign_us / encode_us, decode_us, check_us,
              check_us / decode_us, checksum == 0 ? " (nothing encoded?)" : "");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("Cost of signing and checking a command and a calibration with the rig key, beside encoding them.",
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
  return 0;
}
