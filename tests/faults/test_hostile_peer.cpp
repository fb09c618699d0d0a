// A hostile peer on the bus (docs/security.md), against
// real processes over udpm: it cannot make a process write outside its
// output folders, cannot lose accepted views, and, once the processes have
// the rig key, cannot command them or swap the calibration at all: unsigned,
// foreign-key, altered and replayed messages are refused and counted with
// their reason.
#include <gtest/gtest.h>
#include <signal.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <sstream>

#include <Eigen/Geometry>

#include "auth/message_auth.h"
#include "bad_messages.h"
#include "bus_watch.h"
#include "cloud_test_support.h"
#include "lcm_io/channels.h"
#include "lcm_io/decode.h"
#include "match_fixtures.h"
#include "rig/rig_message.h"
#include "runtime/wall_clock.h"
#include "test_support.h"
#include "widestereo/calibration_status_t.hpp"
#include "widestereo/calibration_views_t.hpp"
#include "widestereo/stereo_calibration_t.hpp"
#include "widestereo/stereo_corners_t.hpp"

namespace {

using namespace ws::test;
namespace ch = ws::channel;
namespace fs = std::filesystem;

// Publishes `bytes` on `channel` and waits for a heartbeat that counts them
// there; returns that heartbeat's last error.
std::string SendAndCount(BusWatch& bus, const std::string& channel, const std::vector<uint8_t>& bytes) {
  const int64_t before = bus.Counters(channel).received;
  bus.Publish(channel, bytes);
  EXPECT_TRUE(bus.ListenUntil(20, [&] { return bus.Counters(channel).received > before; }))
      << "no heartbeat counted the message on " << channel;
  return bus.status() ? bus.status()->last_error : "";
}

// stereo-command as a user runs it, with `args` after the command name.
void RunStereoCommand(const std::string& dir, const std::string& url, std::vector<std::string> args) {
  args.insert(args.begin(), "stereo-command");
  args.insert(args.end(), {"--out-url", url, "--log-dir", dir, "--quiet"});
  const CommandResult r = RunCommand(args, 30);
  EXPECT_EQ(r.exit_code, 0) << r.output;
}

// The payload `bus` collected on STEREO_COMMAND whose arguments are `args`.
std::vector<uint8_t> CollectedCommand(BusWatch& bus, const std::vector<std::string>& args) {
  for (const auto& bytes : bus.Payloads(ch::kStereoCommand)) {
    widestereo::command_t command;
    if (command.decode(bytes.data(), 0, int(bytes.size())) > 0 && command.args == args) return bytes;
  }
  ADD_FAILURE() << "no command with those arguments was heard";
  return {};
}

// stereo-calibrate over udpm, poly6 (the quickest solve), and the bus seen from here.
std::vector<std::string> CalibrateArgv(const std::string& dir, const std::string& url,
                                       const std::vector<std::string>& extra) {
  // poly6 and no non-radial field: a quick solve (what is checked here is
  // what the process does with commands, not the lens model).
  std::vector<std::string> argv = {"stereo-calibrate", "--model", "poly6", "--nonradial", "none", "--log-dir", dir,
                                   "--in-url",         url,       "--out-url", url};
  argv.insert(argv.end(), extra.begin(), extra.end());
  return argv;
}

widestereo::calibration_status_t LastCalibrationStatus(BusWatch& bus) {
  const auto& statuses = bus.Payloads(ch::kCalibrationStatus);
  if (statuses.empty()) return {};
  return ws::DecodeMessage<widestereo::calibration_status_t>(statuses.back().data(), int(statuses.back().size()));
}

// The 30 views of logs/sim-corners.lcmlog.
std::vector<widestereo::stereo_corners_t> RealViews() {
  std::vector<widestereo::stereo_corners_t> views;
  for (const LogEvent& e : ReadLog(SourceDir() + "/logs/sim-corners.lcmlog"))
    if (e.channel == ch::kStereoCorners)
      views.push_back(ws::DecodeMessage<widestereo::stereo_corners_t>(e.data.data(), int(e.data.size())));
  return views;
}

// Sends the 30 views of logs/sim-corners.lcmlog, signed as stereo-detect
// signs them where a key is given; returns how many views stereo-calibrate
// kept (0, and a failure, if it never counted them all).
int SendViews(BusWatch& bus, const ws::auth::RigKey* key = nullptr) {
  const int64_t received = bus.Counters(ch::kStereoCorners).received;
  int sent = 0;
  for (widestereo::stereo_corners_t view : RealViews()) {
    if (key) ws::auth::Sign(*key, ch::kStereoCorners, "stereo-detect test", ws::WallMicros(), view);
    bus.Publish(ch::kStereoCorners, Encoded(view));
    bus.Listen(0.02);
    ++sent;
  }
  EXPECT_TRUE(bus.ListenUntil(20, [&] { return bus.Counters(ch::kStereoCorners).received == received + sent; }));
  bus.Listen(1.5);  // a CALIBRATION_STATUS after the last view
  return LastCalibrationStatus(bus).views_stereo;
}

// Sends a command to stereo-calibrate; true once a CALIBRATION_STATUS says `done`.
bool CommandCalibrate(BusWatch& bus, const widestereo::command_t& command,
                      const std::function<bool(const widestereo::calibration_status_t&)>& done) {
  const size_t seen = bus.Payloads(ch::kCalibrationStatus).size();
  bus.Publish(ch::kStereoCommand, command);
  return bus.ListenUntil(
      120, [&] { return bus.Payloads(ch::kCalibrationStatus).size() > seen && done(LastCalibrationStatus(bus)); });
}

bool Solved(const widestereo::calibration_status_t& s) { return s.state == "solved"; }

TEST(HostilePeer, StereoCloudSavesOnlyIntoItsPcdFolder) {
  const std::string dir = TempDir("hostile-cloud-paths");
  const std::string url = UniqueUdpmUrl(16);
  Command process({"stereo-cloud", "--pcd-dir", dir + "/pcd", "--save-every", "0", "--log-dir", dir, "--in-url", url,
                   "--out-url", url});
  BusWatch bus(url, "stereo-cloud");
  ASSERT_TRUE(bus.ListenUntil(20, [&] { return bus.status().has_value(); })) << process.Output();
  SendAndCount(bus, ch::kStereoCloud, Encoded(ws::testing::MakeCloud({{0, 0, 1}, {1, 0, 1}, {0, 1, 1}})));

  for (const std::string& path : {dir + "/outside.pcd", std::string("../x.pcd"), std::string("pcd/../../y.pcd")}) {
    const std::string error =
        SendAndCount(bus, ch::kStereoCommand, Encoded(CommandMessage("save", "stereo-cloud", {"path=" + path})));
    EXPECT_NE(error.find("save: path='" + path + "': not a plain file name"), std::string::npos) << error;
  }
  EXPECT_EQ(bus.Counters(ch::kStereoCommand).rejected, 3);
  SendAndCount(bus, ch::kStereoCommand, Encoded(CommandMessage("save", "stereo-cloud", {"path=inside.pcd"})));
  // Files of another kind, or one already there, are not the cloud's to write.
  std::filesystem::copy_file(dir + "/pcd/inside.pcd", dir + "/pcd/kept.pcd");
  const std::string kept = ReadFileText(dir + "/pcd/kept.pcd");
  for (const char* name : {"path=refined.yaml", "path=run.lcmlog", "path=kept.pcd", "path=a\nb.pcd"})
    SendAndCount(bus, ch::kStereoCommand, Encoded(CommandMessage("save", "stereo-cloud", {name})));
  EXPECT_EQ(bus.Counters(ch::kStereoCommand).rejected, 7);
  SendAndCount(bus, ch::kStereoCommand,
               Encoded(CommandMessage("save", "stereo-cloud", {"path=kept.pcd", "overwrite=1"})));
  process.Signal(SIGINT);
  EXPECT_EQ(process.Wait(30).exit_code, 0);
  EXPECT_EQ(bus.Counters(ch::kStereoCommand).rejected, 7);
  EXPECT_TRUE(fs::exists(dir + "/pcd/inside.pcd"));
  EXPECT_EQ(ReadFileText(dir + "/pcd/kept.pcd.1.bak"), kept) << "the overwritten cloud kept as a backup";
  for (const char* other : {"/pcd/refined.yaml", "/pcd/run.lcmlog"}) EXPECT_FALSE(fs::exists(dir + other)) << other;
  for (const char* outside : {"/outside.pcd", "/x.pcd", "/y.pcd", "/../x.pcd", "/../y.pcd"})
    EXPECT_FALSE(fs::exists(dir + outside)) << outside;
}

TEST(HostilePeer, StereoCalibrateSavesOnlyIntoTheFoldersOfOutAndReport) {
  const std::string dir = TempDir("hostile-calibrate-paths");
  const std::string out = dir + "/out";
  fs::create_directories(out);
  const std::string url = UniqueUdpmUrl(17) + "&recv_buf_size=8388608";
  const std::string state = out + "/stereo-calibrate-views.lcmlog";  // the calibrate launch's layout
  Command process(CalibrateArgv(dir, url, {"--state", state, "--out", out + "/calib.yaml", "--report", out + "/report.json"}));
  BusWatch bus(url, "stereo-calibrate");
  bus.Collect(ch::kCalibrationStatus);
  ASSERT_TRUE(bus.ListenUntil(20, [&] { return bus.status().has_value(); })) << process.Output();
  ASSERT_GT(SendViews(bus), 10);
  ASSERT_TRUE(CommandCalibrate(bus, CommandMessage("solve", "stereo-calibrate"), Solved)) << process.Output();

  for (const std::string& arg : {"path=" + dir + "/outside.yaml", std::string("path=../x.yaml"),
                                 "report=" + dir + "/outside.json", std::string("report=../x.json")}) {
    const std::string error = SendAndCount(bus, ch::kStereoCommand, Encoded(CommandMessage("save", "", {arg})));
    EXPECT_NE(error.find("'" + arg.substr(arg.find('=') + 1) + "': not a plain file name"), std::string::npos)
        << error;
  }
  EXPECT_EQ(bus.Counters(ch::kStereoCommand).rejected, 4);
  // Its own views state, a file of another kind, one already there: refused,
  // and nothing of them touched.
  const std::string views = ReadFileText(state), calib = ReadFileText(out + "/calib.yaml");
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"path=stereo-calibrate-views.lcmlog", "report=calibration.yaml"},
        {"path=calib.yaml"}, {"report=report.json"}, {"path=new.yaml", "overwrite=yes"}})
    SendAndCount(bus, ch::kStereoCommand, Encoded(CommandMessage("save", "", args)));
  EXPECT_EQ(bus.Counters(ch::kStereoCommand).rejected, 8);
  SendAndCount(bus, ch::kStereoCommand, Encoded(CommandMessage("save", "", {"path=again.yaml", "report=again.json"})));
  SendAndCount(bus, ch::kStereoCommand, Encoded(CommandMessage("save", "", {"path=calib.yaml", "overwrite=1"})));
  // Symlinks planted in the folder, to a file outside it: at the temporary
  // name a save once used, and at the final name.
  std::ofstream(dir + "/victim.yaml") << "victim\n";
  fs::create_symlink(dir + "/victim.yaml", out + "/planted.yaml.tmp");
  fs::create_symlink(dir + "/victim.yaml", out + "/linked.yaml");
  SendAndCount(bus, ch::kStereoCommand, Encoded(CommandMessage("save", "", {"path=planted.yaml"})));
  SendAndCount(bus, ch::kStereoCommand, Encoded(CommandMessage("save", "", {"path=linked.yaml", "overwrite=1"})));
  process.Signal(SIGINT);
  EXPECT_EQ(process.Wait(30).exit_code, 0);
  EXPECT_EQ(bus.Counters(ch::kStereoCommand).rejected, 8);
  EXPECT_EQ(ReadFileText(dir + "/victim.yaml"), "victim\n") << "a save wrote through a planted symlink";
  EXPECT_FALSE(fs::is_symlink(out + "/planted.yaml"));
  EXPECT_FALSE(fs::is_symlink(out + "/linked.yaml"));
  EXPECT_EQ(ReadFileText(out + "/planted.yaml"), ReadFileText(out + "/calib.yaml"));
  EXPECT_EQ(ReadFileText(out + "/linked.yaml"), ReadFileText(out + "/calib.yaml"));
  EXPECT_EQ(ReadFileText(state), views);
  EXPECT_FALSE(fs::exists(out + "/calibration.yaml"));
  EXPECT_EQ(ReadFileText(out + "/calib.yaml.1.bak"), calib) << "the overwritten calibration kept";
  EXPECT_EQ(ReadFileText(out + "/again.yaml"), ReadFileText(out + "/calib.yaml"));
  EXPECT_EQ(ReadFileText(out + "/again.json"), ReadFileText(out + "/report.json"));
  for (const char* outside : {"/outside.yaml", "/x.yaml", "/outside.json", "/x.json"})
    EXPECT_FALSE(fs::exists(dir + outside)) << outside;
}

// reset archives the views, restore brings them back, and the solve after
// them is the solve before them, byte for byte; a solve leaves the views as
// they were.
TEST(HostilePeer, ResetThenRestoreThenSolveGivesTheSameCalibration) {
  const std::string dir = TempDir("hostile-calibrate-reset");
  const std::string state = dir + "/views.lcmlog", calib = dir + "/calib.yaml";
  const std::string url = UniqueUdpmUrl(18) + "&recv_buf_size=8388608";
  Command process(CalibrateArgv(dir, url, {"--state", state, "--out", calib}));
  BusWatch bus(url, "stereo-calibrate");
  bus.Collect(ch::kCalibrationStatus);
  ASSERT_TRUE(bus.ListenUntil(20, [&] { return bus.status().has_value(); })) << process.Output();
  const int views = SendViews(bus);
  ASSERT_GT(views, 10);
  const std::string kept = ReadFileText(state);
  ASSERT_TRUE(CommandCalibrate(bus, CommandMessage("solve"), Solved)) << process.Output();
  const std::string before = ReadFileText(calib);
  ASSERT_FALSE(before.empty());
  EXPECT_EQ(ReadFileText(state), kept) << "the solve changed the views";
  EXPECT_EQ(LastCalibrationStatus(bus).views_stereo, views);

  ASSERT_TRUE(CommandCalibrate(bus, CommandMessage("reset"), [](const auto& s) { return s.views_stereo == 0; }));
  std::vector<std::string> archives;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.path().filename().string().rfind("views-", 0) == 0) archives.push_back(entry.path().string());
  ASSERT_EQ(archives.size(), 1u);
  EXPECT_EQ(ReadFileText(archives[0]), kept) << "the archive is the state file as it was";
  fs::remove(calib);

  ASSERT_TRUE(CommandCalibrate(bus, CommandMessage("restore"), [&](const auto& s) { return s.views_stereo == views; }));
  EXPECT_EQ(ReadFileText(state), kept);
  ASSERT_TRUE(CommandCalibrate(bus, CommandMessage("solve"), Solved)) << process.Output();
  process.Signal(SIGINT);
  EXPECT_EQ(process.Wait(30).exit_code, 0);
  EXPECT_EQ(ReadFileText(calib), before);
  EXPECT_EQ(bus.Counters(ch::kStereoCommand).rejected, 0);
}

TEST(HostilePeer, WithTheRigKeyOnlyACommandSignedWithItIsObeyedOnce) {
  const std::string dir = TempDir("hostile-keyed-commands");
  const std::string key = WriteKeyFile(dir, "rig.key"), other = WriteKeyFile(dir, "other.key");
  const std::string url = UniqueUdpmUrl(19);
  const std::vector<std::string> argv = {"stereo-cloud", "--key-file", key,  "--pcd-dir", dir + "/pcd", "--save-every",
                                         "0",            "--log-dir",  dir,  "--in-url",  url,          "--out-url",
                                         url};
  auto process = std::make_unique<Command>(argv);
  BusWatch bus(url, "stereo-cloud");
  bus.Collect(ch::kStereoCommand);
  ASSERT_TRUE(bus.ListenUntil(20, [&] { return bus.status().has_value(); })) << process->Output();
  SendAndCount(bus, ch::kStereoCloud, Encoded(ws::testing::MakeCloud({{0, 0, 1}, {1, 0, 1}, {0, 1, 1}})));

  std::string error = SendAndCount(bus, ch::kStereoCommand,
                                   Encoded(CommandMessage("save", "stereo-cloud", {"path=unsigned.pcd"}, ws::WallMicros())));
  EXPECT_NE(error.find("STEREO_COMMAND: refused: unsigned"), std::string::npos) << error;

  RunStereoCommand(dir, url, {"save", "--target", "stereo-cloud", "--arg", "path=other.pcd", "--key-file", other});
  ASSERT_TRUE(bus.ListenUntil(20, [&] { return bus.Counters(ch::kStereoCommand).received == 2; }));
  error = bus.status()->last_error;
  EXPECT_NE(error.find("refused: signed with another rig key"), std::string::npos) << error;

  RunStereoCommand(dir, url, {"save", "--target", "stereo-cloud", "--arg", "path=signed.pcd", "--key-file", key});
  ASSERT_TRUE(bus.ListenUntil(20, [&] { return bus.Counters(ch::kStereoCommand).received == 3; }));
  EXPECT_EQ(bus.Counters(ch::kStereoCommand).rejected, 2);
  EXPECT_TRUE(fs::exists(dir + "/pcd/signed.pcd"));
  fs::remove(dir + "/pcd/signed.pcd");

  // Signed by a sender whose clock runs 20 s fast: refused, so that its
  // bytes cannot be replayed to a process started after it was sent.
  widestereo::command_t ahead = CommandMessage("save", "stereo-cloud", {"path=ahead.pcd"});
  ws::auth::Sign(ws::auth::RigKey::FromFile(key), ch::kStereoCommand, "fast clock", ws::WallMicros() + 20'000'000,
                 ahead);
  error = SendAndCount(bus, ch::kStereoCommand, Encoded(ahead));
  EXPECT_NE(error.find("refused: dated 20"), std::string::npos) << error;

  const std::vector<uint8_t> signed_save = CollectedCommand(bus, {"path=signed.pcd"});
  error = SendAndCount(bus, ch::kStereoCommand, signed_save);  // byte for byte
  EXPECT_NE(error.find("refused: replayed"), std::string::npos) << error;
  widestereo::command_t altered;
  ASSERT_GT(altered.decode(signed_save.data(), 0, int(signed_save.size())), 0);
  altered.args = {"path=altered.pcd"};
  error = SendAndCount(bus, ch::kStereoCommand, Encoded(altered));
  EXPECT_NE(error.find("refused: its MAC does not match"), std::string::npos) << error;

  process->Signal(SIGINT);
  EXPECT_EQ(process->Wait(30).exit_code, 0);
  EXPECT_EQ(bus.Counters(ch::kStereoCommand).received, 6);
  EXPECT_EQ(bus.Counters(ch::kStereoCommand).rejected, 5);

  // Restarted, it knows none of the nonces it accepted: what was signed before its start is refused.
  process = std::make_unique<Command>(argv);
  ASSERT_TRUE(bus.ListenUntil(20, [&] { return bus.status() && bus.status()->pid == process->pid(); }));
  SendAndCount(bus, ch::kStereoCloud, Encoded(ws::testing::MakeCloud({{0, 0, 1}, {1, 0, 1}, {0, 1, 1}})));
  error = SendAndCount(bus, ch::kStereoCommand, signed_save);
  EXPECT_NE(error.find("before this process started"), std::string::npos) << error;
  process->Signal(SIGINT);
  EXPECT_EQ(process->Wait(30).exit_code, 0);
  EXPECT_EQ(bus.Counters(ch::kStereoCommand).rejected, 1);
  EXPECT_TRUE(fs::is_empty(dir + "/pcd")) << "only the signed save wrote, once";
}

TEST(HostilePeer, WithTheRigKeyStereoMatchAdoptsOnlyTheCalibrationSignedWithIt) {
  const std::string dir = TempDir("hostile-keyed-calibration");
  const std::string key = WriteKeyFile(dir, "rig.key");
  const std::string url = UniqueUdpmUrl(20) + "&recv_buf_size=8388608";
  Command match({"stereo-match", "--key-file", key, "--log-dir", dir, "--in-url", url, "--out-url", url});
  BusWatch bus(url, "stereo-match");
  bus.Collect(ch::kStereoCalibration);
  ASSERT_TRUE(bus.ListenUntil(20, [&] { return bus.status().has_value(); })) << match.Output();

  auto forged = IdentityCalibration(320, 240, 300, 0.1);
  forged.utime = ws::WallMicros();
  std::string error = SendAndCount(bus, ch::kStereoCalibration, Encoded(forged));
  EXPECT_NE(error.find("STEREO_CALIBRATION: refused: unsigned"), std::string::npos) << error;
  ws::auth::Sign(ws::auth::RigKey::FromFile(WriteKeyFile(dir, "other.key")), ch::kStereoCalibration, "forger",
                 ws::WallMicros(), forged);
  error = SendAndCount(bus, ch::kStereoCalibration, Encoded(forged));
  EXPECT_NE(error.find("refused: signed with another rig key"), std::string::npos) << error;
  EXPECT_EQ(bus.status()->state, "waiting for calibration") << "a refused calibration built maps";

  Command calibrate(CalibrateArgv(dir, url, {"--key-file", key, "--state", "none"}));
  BusWatch calibrate_bus(url, "stereo-calibrate");
  calibrate_bus.Collect(ch::kCalibrationStatus);
  ASSERT_TRUE(calibrate_bus.ListenUntil(20, [&] { return calibrate_bus.status().has_value(); })) << calibrate.Output();
  const ws::auth::RigKey rig_key = ws::auth::RigKey::FromFile(key);
  ASSERT_GT(SendViews(calibrate_bus, &rig_key), 10);
  RunStereoCommand(dir, url, {"solve", "--key-file", key});
  ASSERT_TRUE(bus.ListenUntil(180, [&] { return bus.status()->state == "matching"; })) << calibrate.Output();
  EXPECT_EQ(bus.Counters(ch::kStereoCalibration).rejected, 2);

  ASSERT_FALSE(bus.Payloads(ch::kStereoCalibration).empty());
  const std::vector<uint8_t> adopted = bus.Payloads(ch::kStereoCalibration).back();
  error = SendAndCount(bus, ch::kStereoCalibration, adopted);
  EXPECT_NE(error.find("refused: replayed"), std::string::npos) << error;
  calibrate.Signal(SIGINT);
  match.Signal(SIGINT);
  EXPECT_EQ(calibrate.Wait(30).exit_code, 0);
  EXPECT_EQ(match.Wait(30).exit_code, 0);
  EXPECT_EQ(bus.Counters(ch::kStereoCalibration).rejected, 3);
  const std::string log = ReadFileText(dir + "/stereo-match.log");
  EXPECT_EQ(log.find("rectification maps for"), log.rfind("rectification maps for")) << "maps built once";
}

// Corner floods: boards of 10^5 points are refused as they arrive (a board
// has its own corners at most), and the session keeps at most --max-views
// views; each refusal is counted with its reason, and the views file holds
// only the views kept.
TEST(HostilePeer, CornerFloodsAreRefusedAndTheSessionCapped) {
  const std::string dir = TempDir("hostile-corner-flood");
  const std::string url = UniqueUdpmUrl(23) + "&recv_buf_size=8388608";
  const std::string state = dir + "/views.lcmlog";
  Command calibrate(CalibrateArgv(dir, url, {"--state", state, "--max-views", "5"}));
  BusWatch bus(url, "stereo-calibrate");
  bus.Collect(ch::kCalibrationStatus);
  ASSERT_TRUE(bus.ListenUntil(20, [&] { return bus.status().has_value(); })) << calibrate.Output();

  const std::vector<widestereo::stereo_corners_t> real = RealViews();
  for (int i = 0; i < 8; ++i) {
    widestereo::stereo_corners_t flood = real[size_t(i)];
    flood.left.n = 100000;
    flood.left.ids.resize(100000, 0);
    flood.left.image_points.resize(100000, flood.left.image_points[0]);
    flood.left.object_points.resize(100000, flood.left.object_points[0]);
    bus.Publish(ch::kStereoCorners, Encoded(flood));
    ASSERT_TRUE(bus.ListenUntil(20, [&] { return bus.Counters(ch::kStereoCorners).rejected == i + 1; }))
        << bus.Counters(ch::kStereoCorners).rejected;
  }
  EXPECT_NE(bus.status()->last_error.find("100000 corners on a board of 54"), std::string::npos)
      << bus.status()->last_error;

  SendViews(bus);
  const int64_t beyond = int64_t(real.size()) - 5;
  ASSERT_TRUE(bus.ListenUntil(20, [&] { return bus.Counters(ch::kStereoCorners).rejected == 8 + beyond; }))
      << bus.Counters(ch::kStereoCorners).rejected;
  EXPECT_NE(bus.status()->last_error.find("maximum of 5 views (--max-views)"), std::string::npos)
      << bus.status()->last_error;
  calibrate.Signal(SIGINT);
  EXPECT_EQ(calibrate.Wait(30).exit_code, 0);
  int kept = 0;
  for (const LogEvent& e : ReadLog(state)) kept += e.channel == ch::kStereoCorners;
  EXPECT_EQ(kept, 5);
  EXPECT_LT(fs::file_size(state), 100000u) << "a flooded view (4.4 MB) was kept";

  // The log does not flood: the refusals of one shape are written once
  // (sent within a second: within the 10 s of the limit), the others counted.
  std::istringstream log(ReadFileText(dir + "/stereo-calibrate.log"));
  int written = 0, counted = 0;
  for (std::string line; std::getline(log, line);) {
    if (line.find("maximum of 5 views") == std::string::npos) continue;
    if (const size_t like = line.find(" lines like '"); like != std::string::npos) {
      counted += std::stoi(line.substr(line.rfind(' ', like - 1) + 1));
    } else {
      ++written;
    }
  }
  EXPECT_EQ(written, 1);
  EXPECT_EQ(written + counted, beyond) << "every refusal is written or counted";
}

// The views of a peer without the key, sent before the real ones: every
// view with its right image turned 1 degree about the image centre (a
// calibration of R off by 1 degree, at a low RMS), and one of another board
// (whose id would make the session refuse the real board). With the key
// neither enters the session: the real, signed views that follow are all
// kept, and the solve's R is the real rig's.
TEST(HostilePeer, WithTheRigKeyUnsignedCornersNeverEnterTheSession) {
  const std::string dir = TempDir("hostile-keyed-corners");
  const std::string key = WriteKeyFile(dir, "rig.key");
  const std::string url = UniqueUdpmUrl(22);
  Command calibrate(CalibrateArgv(dir, url, {"--key-file", key, "--state", dir + "/views.lcmlog"}));
  BusWatch bus(url, "stereo-calibrate");
  bus.Collect(ch::kCalibrationStatus);
  bus.Collect(ch::kStereoCalibration);
  ASSERT_TRUE(bus.ListenUntil(20, [&] { return bus.status().has_value(); })) << calibrate.Output();

  const double turn = M_PI / 180;
  std::vector<widestereo::stereo_corners_t> attack = RealViews();
  for (auto& view : attack) {
    const double cx = view.right.image_width / 2.0, cy = view.right.image_height / 2.0;
    for (auto& p : view.right.image_points) {
      const double x = p[0] - cx, y = p[1] - cy;
      p[0] = cx + std::cos(turn) * x - std::sin(turn) * y;
      p[1] = cy + std::sin(turn) * x + std::cos(turn) * y;
    }
  }
  attack.push_back(attack.front());
  attack.back().left.board_id = attack.back().right.board_id = "chessboard:9x6:0.1";
  for (const auto& view : attack) {
    bus.Publish(ch::kStereoCorners, Encoded(view));
    bus.Listen(0.02);
  }
  ASSERT_TRUE(bus.ListenUntil(20, [&] { return bus.Counters(ch::kStereoCorners).rejected == int64_t(attack.size()); }))
      << bus.Counters(ch::kStereoCorners).rejected;
  EXPECT_NE(bus.status()->last_error.find("STEREO_CORNERS: refused: unsigned"), std::string::npos)
      << bus.status()->last_error;

  const ws::auth::RigKey rig_key = ws::auth::RigKey::FromFile(key);
  int left = 0, right = 0, stereo = 0;
  for (const auto& view : RealViews()) {
    left += view.left.n > 0;
    right += view.right.n > 0;
    stereo += view.left.n > 0 && view.right.n > 0;
  }
  EXPECT_EQ(SendViews(bus, &rig_key), stereo) << "a real view refused as a near duplicate or another board";
  EXPECT_EQ(LastCalibrationStatus(bus).views_left, left);
  EXPECT_EQ(LastCalibrationStatus(bus).views_right, right);
  EXPECT_EQ(bus.Counters(ch::kStereoCorners).rejected, int64_t(attack.size()));
  RunStereoCommand(dir, url, {"solve", "--key-file", key});
  ASSERT_TRUE(bus.ListenUntil(180, [&] { return Solved(LastCalibrationStatus(bus)); })) << calibrate.Output();
  ASSERT_TRUE(bus.ListenUntil(20, [&] { return !bus.Payloads(ch::kStereoCalibration).empty(); }));
  const auto& published = bus.Payloads(ch::kStereoCalibration).back();
  const ws::Rig solved = ws::RigFromMessage(
      ws::DecodeMessage<widestereo::stereo_calibration_t>(published.data(), int(published.size())));
  // The simulated rig's R is the identity (logs/sim-images.truth.yaml).
  const double off_deg = Eigen::AngleAxisd(solved.R).angle() * 180 / M_PI;
  EXPECT_LT(off_deg, 0.25) << "R is off by the attack's turn";
  calibrate.Signal(SIGINT);
  EXPECT_EQ(calibrate.Wait(30).exit_code, 0);
}

// A removal is a user's: with the rig key only a signed one is obeyed. An
// unsigned one and one naming no view are refused and counted; the view
// removed is gone from CALIBRATION_VIEWS and from the views file, so a
// restart does not bring it back.
TEST(HostilePeer, WithTheRigKeyOnlyASignedRemoveTakesAViewOutOfTheCalibration) {
  const std::string dir = TempDir("hostile-keyed-remove");
  const std::string key = WriteKeyFile(dir, "rig.key");
  const std::string url = UniqueUdpmUrl(24) + "&recv_buf_size=8388608";
  const auto argv = CalibrateArgv(dir, url, {"--key-file", key, "--state", dir + "/views.lcmlog"});
  auto calibrate = std::make_unique<Command>(argv);
  BusWatch bus(url, "stereo-calibrate");
  bus.Collect(ch::kCalibrationStatus);
  bus.Collect(ch::kCalibrationViews);
  ASSERT_TRUE(bus.ListenUntil(20, [&] { return bus.status().has_value(); })) << calibrate->Output();
  const ws::auth::RigKey rig_key = ws::auth::RigKey::FromFile(key);
  ASSERT_GT(SendViews(bus, &rig_key), 10);
  using View = std::pair<int64_t, int64_t>;  // frame id, utime
  auto listed = [&] {
    std::vector<View> views;
    if (bus.Payloads(ch::kCalibrationViews).empty()) return views;
    const auto& bytes = bus.Payloads(ch::kCalibrationViews).back();
    for (const auto& v : ws::DecodeMessage<widestereo::calibration_views_t>(bytes.data(), int(bytes.size())).views)
      views.emplace_back(v.frame_id, v.frame_utime);
    return views;
  };
  const std::vector<View> before = listed();
  ASSERT_GT(before.size(), 10u);
  const auto [frame, utime] = before[3];
  const std::vector<std::string> args = {"frame=" + std::to_string(frame), "utime=" + std::to_string(utime)};

  std::string error = SendAndCount(
      bus, ch::kStereoCommand, Encoded(CommandMessage("remove", "stereo-calibrate", args, ws::WallMicros())));
  EXPECT_NE(error.find("STEREO_COMMAND: refused: unsigned"), std::string::npos) << error;
  RunStereoCommand(dir, url, {"remove", "--target", "stereo-calibrate", "--arg", "frame=999999", "--key-file", key});
  ASSERT_TRUE(bus.ListenUntil(20, [&] { return bus.Counters(ch::kStereoCommand).rejected == 2; }));
  EXPECT_NE(bus.status()->last_error.find("no view of frame 999999"), std::string::npos) << bus.status()->last_error;
  EXPECT_EQ(listed(), before);

  RunStereoCommand(dir, url, {"remove", "--target", "stereo-calibrate", "--arg", args[0], "--arg", args[1],
                              "--key-file", key});
  std::vector<View> after = before;
  after.erase(after.begin() + 3);
  EXPECT_TRUE(bus.ListenUntil(20, [&] { return listed() == after; })) << calibrate->Output();
  EXPECT_EQ(bus.Counters(ch::kStereoCommand).rejected, 2);
  calibrate->Signal(SIGINT);
  EXPECT_EQ(calibrate->Wait(30).exit_code, 0);

  calibrate = std::make_unique<Command>(argv);
  // The restarted process's own list: once it says it runs (its signal
  // handlers are in place), not a list of the one before still on its way.
  ASSERT_TRUE(bus.ListenUntil(20, [&] { return bus.status() && bus.status()->pid == calibrate->pid(); }))
      << calibrate->Output();
  bus.TakePayloads(ch::kCalibrationViews);
  EXPECT_TRUE(bus.ListenUntil(20, [&] { return !listed().empty(); })) << calibrate->Output();
  EXPECT_EQ(listed(), after) << "the views file brought the removed view back";
  calibrate->Signal(SIGINT);
  EXPECT_EQ(calibrate->Wait(30).exit_code, 0);
}

}  // namespace
