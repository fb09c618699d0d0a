// The rig key and the MAC of commands and calibrations (auth/): what a keyed
// receiver accepts and what it refuses, with the reason it gives.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>

#include "auth/message_auth.h"
#include "lcm_io/channels.h"
#include "rectify/stereo_rig.h"
#include "test_support.h"
#include "widestereo/stereo_calibration_t.hpp"

namespace {

using ws::auth::AuthCheck;
using ws::auth::AuthError;
using ws::auth::RigKey;
namespace ch = ws::channel;

constexpr int64_t kNow = 1764619200000000;  // 2025-12-01 20:00 UTC

const RigKey& Key() {
  static const RigKey key = RigKey::FromSecret("the secret of the rig in these tests, 32+ bytes");
  return key;
}

widestereo::command_t Signed(const std::string& channel = ch::kStereoCommand, int64_t utime = kNow) {
  widestereo::command_t command = ws::test::CommandMessage("save", "stereo-cloud", {"path=cloud.pcd"}, utime);
  ws::auth::Sign(Key(), channel, "test", utime, command);
  return command;
}

// The reason Check gives for refusing msg ("" when it accepts it).
template <class Msg>
std::string Refusal(AuthCheck& check, const Msg& msg, const std::string& channel = ch::kStereoCommand,
                    int64_t now = kNow) {
  try {
    check.Check(channel, msg, now);
    return "";
  } catch (const AuthError& e) {
    return e.what();
  }
}

TEST(MessageAuth, ASignedMessageIsAcceptedOnceAndEveryChangeIsRefused) {
  AuthCheck check(Key());
  const widestereo::command_t command = Signed();
  EXPECT_EQ(command.auth.key_id, Key().id());
  EXPECT_EQ(command.auth.sender, "test");
  EXPECT_EQ(Refusal(check, command), "");
  EXPECT_NE(Refusal(check, command).find("refused: replayed (nonce "), std::string::npos);

  auto altered = Signed();
  altered.args = {"path=other.pcd"};
  EXPECT_EQ(Refusal(check, altered), "refused: its MAC does not match (changed after signing, or forged)");
  altered = Signed();
  altered.auth.sender = "someone else";
  EXPECT_NE(Refusal(check, altered).find("MAC does not match"), std::string::npos);
  altered = Signed();
  altered.auth.mac[31] ^= 1;
  EXPECT_NE(Refusal(check, altered).find("MAC does not match"), std::string::npos);
  // Signed for one channel, it is refused on another.
  EXPECT_NE(Refusal(check, Signed(ch::kStereoCalibration)).find("MAC does not match"), std::string::npos);
}

TEST(MessageAuth, UnsignedForeignStaleAndFutureMessagesAreRefusedWithTheirReason) {
  AuthCheck check(Key());
  widestereo::command_t unsigned_command = ws::test::CommandMessage("save");
  unsigned_command.auth = widestereo::auth_t{};  // what a process without a key sends
  EXPECT_EQ(Refusal(check, unsigned_command), "refused: unsigned, and this process requires the rig key's MAC");

  const RigKey other = RigKey::FromSecret("another rig's secret, also 32 bytes or more");
  EXPECT_NE(other.id(), Key().id());
  widestereo::command_t foreign = ws::test::CommandMessage("save");
  ws::auth::Sign(other, ch::kStereoCommand, "other rig", kNow, foreign);
  EXPECT_EQ(Refusal(check, foreign), "refused: signed with another rig key (key id " + other.IdText() +
                                         ", this rig's is " + Key().IdText() + ")");

  EXPECT_EQ(Refusal(check, Signed(ch::kStereoCommand, kNow - 31000000)),
            "refused: signed 31.0 s before this process's clock, outside the 30.0 s window (a replay, or clocks "
            "apart)");
  EXPECT_EQ(Refusal(check, Signed(ch::kStereoCommand, kNow + 2500000)),
            "refused: dated 2.5 s after this process's clock, more than the 2.0 s allowed (clocks apart: "
            "synchronise them, or --max-clock-skew)");
  EXPECT_EQ(Refusal(check, Signed(ch::kStereoCommand, kNow + 1500000)), "");
  EXPECT_EQ(Refusal(check, Signed(ch::kStereoCommand, kNow - 29000000)), "");
}

// A sender whose clock runs 20 s fast: its command is refused, so it cannot
// be obeyed, then replayed to a receiver started after it was sent (whose
// "signed before I started" it would pass). The skew allowed is the
// receiver's to set.
TEST(MessageAuth, ACommandDatedAheadOfTheReceiversClockIsRefused) {
  const widestereo::command_t ahead = Signed(ch::kStereoCommand, kNow + 20000000);
  AuthCheck receiver(Key(), kNow - 1000000);
  EXPECT_NE(Refusal(receiver, ahead).find("dated 20.0 s after"), std::string::npos);
  AuthCheck restarted(Key(), kNow + 5000000);  // started after the command was sent
  EXPECT_NE(Refusal(restarted, ahead, ch::kStereoCommand, kNow + 6000000).find("dated 14.0 s after"),
            std::string::npos);
  AuthCheck lenient(Key(), kNow - 1000000, 25000000);
  EXPECT_EQ(Refusal(lenient, ahead), "");
}

// A receiver that starts afresh knows no nonce: what was signed before its
// start is refused, so a message an earlier run obeyed cannot be replayed.
TEST(MessageAuth, WhatWasSignedBeforeTheReceiverStartedIsRefused) {
  AuthCheck check(Key(), kNow);
  EXPECT_EQ(Refusal(check, Signed(ch::kStereoCommand, kNow - 500000)),
            "refused: signed 0.5 s before this process started (a replay, or clocks apart)");
  EXPECT_EQ(Refusal(check, Signed(ch::kStereoCommand, kNow)), "");
}

// The nonces of messages older than the window are forgotten; such a
// message is refused by its age, so a replay never gets through.
TEST(MessageAuth, AReplayIsRefusedAlsoAfterTheWindow) {
  AuthCheck check(Key());
  const widestereo::command_t command = Signed();
  EXPECT_EQ(Refusal(check, command), "");
  EXPECT_NE(Refusal(check, Signed(), ch::kStereoCommand, kNow + 40000000).find("before this process's clock"),
            std::string::npos);
  EXPECT_NE(Refusal(check, command, ch::kStereoCommand, kNow + 40000000).find("outside the 30.0 s window"),
            std::string::npos);
}

TEST(MessageAuth, ACalibrationIsSignedOverEveryField) {
  AuthCheck check(Key());
  ws::StereoRig rig = ws::StereoRigFromFile(ws::test::SourceDir() + "/config/calib/sim-default.yaml");
  widestereo::stereo_calibration_t calibration = ws::MessageFromStereoRig(rig, kNow);
  ws::auth::Sign(Key(), ch::kStereoCalibration, "stereo-calibrate", kNow, calibration);
  auto moved = calibration;
  moved.T[0] += 1e-9;
  EXPECT_NE(Refusal(check, moved, ch::kStereoCalibration).find("MAC does not match"), std::string::npos);
  EXPECT_EQ(Refusal(check, calibration, ch::kStereoCalibration), "");
}

TEST(RigKey, OnlyAFileItsOwnerAloneCanReadOfEnoughBytesIsAKey) {
  const std::string dir = ws::test::TempDir("rig-key");
  const std::string good = ws::test::WriteKeyFile(dir, "good.key");
  EXPECT_EQ(RigKey::FromFile(good).id(), RigKey::FromFile(good).id());
  EXPECT_NE(RigKey::FromFile(good).id(), RigKey::FromFile(ws::test::WriteKeyFile(dir, "other.key")).id());
  EXPECT_NO_THROW(RigKey::FromFile(ws::test::WriteKeyFile(dir, "read-only.key", 0400)));

  auto refusal = [](const std::string& path) -> std::string {
    try {
      RigKey::FromFile(path);
      return "";
    } catch (const ws::auth::KeyFileError& e) {
      return e.what();
    }
  };
  const std::string shared = ws::test::WriteKeyFile(dir, "shared.key", 0640);
  EXPECT_EQ(refusal(shared), "--key-file " + shared + ": mode 0640 lets others read or change it; only its owner may "
                             "(chmod 600 " + shared + ")");
  EXPECT_NE(refusal(ws::test::WriteKeyFile(dir, "world.key", 0604)).find("mode 0604"), std::string::npos);
  EXPECT_EQ(refusal(dir + "/none.key"), "--key-file " + dir + "/none.key: cannot be read");
  const std::string short_key = dir + "/short.key";
  std::ofstream(short_key) << "too short";
  chmod(short_key.c_str(), 0600);
  EXPECT_NE(refusal(short_key).find("needs at least 32 bytes of secret, this has 9"), std::string::npos);
  EXPECT_NE(refusal(dir).find("not a regular file"), std::string::npos);
}

}  // namespace
