#include "bad_peer.h"

#include <gtest/gtest.h>

#include <cstdio>

namespace ws::test {

std::vector<std::vector<uint8_t>> CleanRun(const std::string& dir, const std::vector<LogEvent>& in,
                                           std::vector<std::string> argv, const std::string& channel) {
  WriteLog(dir + "/clean-in.lcmlog", in);
  argv.insert(argv.end(), {"--log-dir", dir, "--in-url", "file://" + dir + "/clean-in.lcmlog?speed=0",
                           "--out-url", "file://" + dir + "/clean-out.lcmlog?mode=w"});
  const auto r = RunCommand(argv, 180);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  std::vector<std::vector<uint8_t>> payloads;
  for (const auto& e : ReadLog(dir + "/clean-out.lcmlog"))
    if (e.channel == channel) payloads.push_back(e.data);
  return payloads;
}

std::vector<std::string> BadPeer::KeyArgs(const std::string& dir) {
  if (!keyed()) return {};
  const std::string file = WriteKeyFile(dir, "rig.key");
  key_ = ws::auth::RigKey::FromFile(file);
  return {"--key-file", file};
}

void Flood(BusWatch& bus, const std::vector<BadChannel*>& channels) {
  for (int i = 0; i < kBadPerGoodFrame; ++i)
    for (BadChannel* c : channels) {
      bus.Publish(c->channel, c->messages.Next());
      ++c->sent;
      bus.Listen(kBadSpacingS);
    }
}

void ExpectRejectedAllBad(const BusWatch& bus, const BadChannel& bad, int good) {
  const auto c = bus.Counters(bad.channel);
  std::printf("%s: %d good and %d bad sent; received %ld, rejected %ld, dropped %ld\n",
              bad.channel.c_str(), good, bad.sent, long(c.received), long(c.rejected), long(c.dropped));
  EXPECT_EQ(c.received, good + c.rejected) << bad.channel;
  EXPECT_EQ(c.dropped, 0) << bad.channel;
  EXPECT_GE(c.rejected, bad.sent / 2) << bad.channel;
  EXPECT_LE(c.rejected, bad.sent) << bad.channel;
}

INSTANTIATE_TEST_SUITE_P(RigKey, BadPeer, ::testing::Bool(),
                         [](const ::testing::TestParamInfo<bool>& info) { return info.param ? "Keyed" : "Keyless"; });

}  // namespace ws::test
