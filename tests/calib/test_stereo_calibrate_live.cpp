// stereo-calibrate live over udpm: CALIBRATION_STATUS at least once a second
// with coverage and a hint, near-duplicate views skipped, the accepted views
// kept in the state file so that a SIGKILLed process resumes with them, and
// a 'solve' command answered with STEREO_CALIBRATION; before it, the
// projection uncertainty of the views so far on CALIBRATION_PREVIEW; a damaged state file
// kept as an archive and every intact view after the damage recovered; a
// views file that cannot be written said on the terminal under --quiet.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <functional>
#include <lcm/lcm-cpp.hpp>
#include <thread>

#include "calib/node/corners_message.h"
#include "calib_test_rigs.h"
#include "lcm_io/channels.h"
#include "lcm_io/lcm_log.h"
#include "test_support.h"
#include "widestereo/calibration_result_t.hpp"
#include "widestereo/calibration_status_t.hpp"
#include "widestereo/command_t.hpp"
#include "widestereo/process_status_t.hpp"
#include "widestereo/stereo_calibration_t.hpp"

namespace {

using namespace ws::calib;
using namespace ws::calib::test;
using Clock = std::chrono::steady_clock;

// Everything stereo-calibrate says on the bus.
struct Bus {
  // Function subscriptions: LCM 1.3.1's member-function ones trip GCC's
  // UBSan alignment check inside lcm-cpp-impl.hpp in make test-asan.
  explicit Bus(const std::string& url) : lcm(url) {
    lcm.subscribeFunction(
        ws::channel::kCalibrationStatus,
        +[](const lcm::ReceiveBuffer*, const std::string&, const widestereo::calibration_status_t* s, Bus* bus) {
          bus->statuses.push_back(*s);
          bus->status_times.push_back(Clock::now());
        },
        this);
    Keep(ws::channel::kStereoCalibration, &calibrations);
    Keep(ws::channel::kCalibrationResult, &results);
    Keep(ws::channel::kCalibrationPreview, &previews);
    lcm.subscribeFunction(
        ws::channel::kProcessStatus,
        +[](const lcm::ReceiveBuffer*, const std::string&, const widestereo::process_status_t* s, Bus* bus) {
          if (s->name != "stereo-calibrate") return;
          bus->pid = s->pid;
          bus->last_error = s->last_error;
        },
        this);
  }
  // Every message of `channel` into `kept`.
  template <class Msg>
  void Keep(const char* channel, std::vector<Msg>* kept) {
    lcm.subscribeFunction(
        channel, +[](const lcm::ReceiveBuffer*, const std::string&, const Msg* m, std::vector<Msg>* to) {
          to->push_back(*m);
        },
        kept);
  }
  // Handles messages until `done` or `seconds` have passed; returns `done`.
  bool Until(double seconds, const std::function<bool()>& done) { return ws::test::HandleUntil(lcm, seconds, done); }
  lcm::LCM lcm;
  std::vector<widestereo::calibration_status_t> statuses;
  std::vector<Clock::time_point> status_times;
  std::vector<widestereo::stereo_calibration_t> calibrations;
  std::vector<widestereo::calibration_result_t> previews, results;
  int pid = 0;
  std::string last_error;  // stereo-calibrate's PROCESS_STATUS
};

// stereo-calibrate on its own thread; a test that fails half way still
// stops it (SIGKILL) before the thread is joined.
struct Running {
  Running(const std::vector<std::string>& argv, Bus* bus) : bus(bus) {
    thread = std::thread([this, argv] { result = ws::test::RunCommand(argv, 60); });
  }
  ~Running() { Stop(SIGKILL); }
  void Stop(int signal) {
    if (!thread.joinable()) return;
    if (bus->pid != 0) kill(bus->pid, signal);
    thread.join();
  }
  Bus* bus;
  std::thread thread;
  ws::test::CommandResult result;
};

widestereo::stereo_corners_t CornersMessage(const SyntheticRig& rig, int v) {
  widestereo::stereo_corners_t msg{};
  msg.utime = 1000 * v;
  msg.frame_id = v;
  msg.left = ToCornersMessage(rig.data.left.views[v], "chessboard:12x9:0.04", 1280, 960);
  msg.right = ToCornersMessage(rig.data.right.views[v], "chessboard:12x9:0.04", 1280, 960);
  return msg;
}

TEST(StereoCalibrateLive, StatusDuplicatesAndViewsThatSurviveAKill) {
  const std::string dir = ws::test::TempDir("calibrate-live");
  const std::string url = ws::test::UniqueUdpmUrl(5);
  const std::string state = dir + "/views.lcmlog";
  SyntheticRigOptions options = BarrelRig();
  options.views = 12;
  const SyntheticRig rig = MakeSyntheticRig(options);
  const std::vector<std::string> argv = {
      "stereo-calibrate", "--in-url", url,       "--out-url", url,     "--log-dir",        dir,
      "--state",          state,      "--model", "poly6",     "--out", dir + "/calib.yaml"};
  Bus bus(url);
  ASSERT_TRUE(bus.lcm.good());
  Running first(argv, &bus);
  ASSERT_TRUE(bus.Until(10, [&] { return bus.pid != 0 && !bus.statuses.empty(); }))
      << "no status from stereo-calibrate";
  for (int v = 0; v < rig.data.size(); ++v) {
    const widestereo::stereo_corners_t msg = CornersMessage(rig, v);
    for (int copy = 0; copy < (v < 3 ? 2 : 1); ++copy) {  // views 0-2 twice: the copies are skipped
      bus.lcm.publish(ws::channel::kStereoCorners, &msg);
      bus.Until(0.02, [] { return false; });
    }
  }
  const int views = rig.data.size();
  ASSERT_TRUE(bus.Until(5, [&] { return bus.statuses.back().views_left == views; }))
      << "views_left " << bus.statuses.back().views_left << " of " << views;
  bus.Until(2.5, [] { return false; });  // a few more statuses
  const widestereo::calibration_status_t& status = bus.statuses.back();
  EXPECT_EQ(status.views_left, views);
  EXPECT_EQ(status.state, "collecting");
  EXPECT_LT(status.rms, 0);
  EXPECT_FALSE(status.hint.empty());
  ASSERT_EQ(status.grid_rows, 6);
  ASSERT_EQ(status.grid_cols, 8);
  int covered = 0;
  for (const auto& row : status.coverage_left)
    for (int count : row) covered += count > 0;
  EXPECT_GT(covered, 10);
  for (size_t i = 1; i < bus.status_times.size(); ++i)
    EXPECT_LE(std::chrono::duration<double>(bus.status_times[i] - bus.status_times[i - 1]).count(),
              1.3);

  // Killed without warning, then started again: the views are back.
  first.Stop(SIGKILL);
  EXPECT_EQ(first.result.exit_code, 128 + SIGKILL);
  EXPECT_EQ(ws::test::ReadLog(state).size(), size_t(views));
  bus.statuses.clear();
  bus.pid = 0;
  Running second(argv, &bus);
  ASSERT_TRUE(bus.Until(10, [&] { return bus.pid != 0 && !bus.statuses.empty(); }));
  EXPECT_EQ(bus.statuses.front().views_left, views);

  widestereo::command_t solve{};
  solve.utime = 0;
  solve.command = "solve";
  solve.target = "";
  solve.nargs = 0;
  bus.lcm.publish(ws::channel::kStereoCommand, &solve);
  ASSERT_TRUE(bus.Until(30, [&] { return !bus.calibrations.empty(); })) << "no STEREO_CALIBRATION";
  EXPECT_EQ(bus.calibrations[0].left.model, "poly6");
  EXPECT_LT(bus.calibrations[0].rms, 0.2);
  ASSERT_TRUE(bus.Until(5, [&] { return bus.statuses.back().state == "solved"; }));
  EXPECT_GT(bus.statuses.back().rms, 0);
  EXPECT_TRUE(std::filesystem::exists(dir + "/calib.yaml"));
  second.Stop(SIGINT);
  EXPECT_EQ(second.result.exit_code, 0) << "Ctrl-C is a clean stop: " << second.result.output;
}

// Live, before a solve, the views so far are solved quickly and their
// projection uncertainty published on CALIBRATION_PREVIEW: each camera's map,
// no calibration published, no file written. Once solved, none follows.
TEST(StereoCalibrateLive, BeforeASolveTheViewsSoFarGiveAnUncertaintyPreview) {
  const std::string dir = ws::test::TempDir("calibrate-live-preview");
  const std::string url = ws::test::UniqueUdpmUrl(8);
  SyntheticRigOptions options = BarrelRig();
  options.views = 8;
  const SyntheticRig rig = MakeSyntheticRig(options);
  // The views in its views file: the first preview has them all.
  std::vector<ws::test::LogEvent> views;
  for (int v = 0; v < rig.data.size(); ++v) views.push_back(ws::test::Event(ws::channel::kStereoCorners, CornersMessage(rig, v)));
  ws::test::WriteLog(dir + "/views.lcmlog", views);
  Bus bus(url);
  ASSERT_TRUE(bus.lcm.good());
  Running process({"stereo-calibrate", "--in-url", url, "--out-url", url, "--log-dir", dir, "--state",
                   dir + "/views.lcmlog", "--model", "poly6", "--nonradial", "none", "--preview-every", "1", "--out",
                   dir + "/calib.yaml"},
                  &bus);
  ASSERT_TRUE(bus.Until(60, [&] { return !bus.previews.empty(); })) << process.result.output;
  EXPECT_EQ(bus.statuses.back().views_left, rig.data.size());
  const widestereo::calibration_result_t& preview = bus.previews.back();
  ASSERT_EQ(preview.nmodels, 1);
  EXPECT_EQ(preview.chosen, "poly6");
  EXPECT_LT(preview.models[0].left_rms, 0.2);
  EXPECT_LT(preview.models[0].right_rms, 0.2);
  ASSERT_EQ(preview.ncameras, 2);
  for (const auto& camera : preview.cameras) ASSERT_GT(camera.uncertainty_rows, 0) << camera.name;
  EXPECT_TRUE(bus.calibrations.empty() && bus.results.empty()) << "a preview published as a calibration";
  EXPECT_FALSE(std::filesystem::exists(dir + "/calib.yaml"));

  widestereo::command_t solve{};
  solve.command = "solve";
  bus.lcm.publish(ws::channel::kStereoCommand, &solve);
  ASSERT_TRUE(bus.Until(60, [&] { return bus.statuses.back().state == "solved" && !bus.results.empty(); }))
      << process.result.output;
  // The median uncertainty: where the preview and the solve are sure alike.
  auto median = [](const widestereo::camera_maps_t& maps) {
    std::vector<double> sigmas;
    for (const auto& row : maps.uncertainty_px)
      for (double sigma : row)
        if (sigma >= 0) sigmas.push_back(sigma);
    std::nth_element(sigmas.begin(), sigmas.begin() + sigmas.size() / 2, sigmas.end());
    return sigmas.empty() ? -1 : sigmas[sigmas.size() / 2];
  };
  for (int c = 0; c < 2; ++c) {  // the solve's shares the board poses between the cameras: somewhat lower
    const double quick = median(preview.cameras[c]), solved = median(bus.results[0].cameras[c]);
    EXPECT_GT(quick, 0.5 * solved) << preview.cameras[c].name;
    EXPECT_LT(quick, 2 * solved) << preview.cameras[c].name;
  }
  const size_t previews = bus.previews.size(), statuses = bus.statuses.size();
  ASSERT_TRUE(bus.Until(10, [&] { return bus.statuses.size() >= statuses + 3; }));
  EXPECT_EQ(bus.previews.size(), previews) << "a preview after the solve";
  process.Stop(SIGINT);
  EXPECT_EQ(process.result.exit_code, 0) << process.result.output;
}

// A views file of 30 views with one byte of the 6th event's sync word
// flipped: stereo-calibrate keeps the file as it was under a name that says
// it is damaged, restores the 29 intact views (the 25 after the damage too),
// says so in its log and status, and appends to the recovered file.
TEST(StereoCalibrateLive, ADamagedViewsFileIsKeptAndEveryIntactViewRecovered) {
  const std::string dir = ws::test::TempDir("calibrate-damaged-views");
  const std::string url = ws::test::UniqueUdpmUrl(6);
  const std::string state = dir + "/views.lcmlog";
  SyntheticRigOptions options = BarrelRig();
  options.views = 31;
  const SyntheticRig rig = MakeSyntheticRig(options);
  std::vector<ws::test::LogEvent> events;
  int64_t sixth = 0;
  for (int v = 0; v < 30; ++v) {
    events.push_back(ws::test::Event(ws::channel::kStereoCorners, CornersMessage(rig, v)));
    if (v < 5) sixth += 4 + 8 + 8 + 4 + 4 + int64_t(events.back().channel.size() + events.back().data.size());
  }
  ws::test::WriteLog(state, events);
  {
    std::fstream file(state, std::ios::in | std::ios::out | std::ios::binary);
    file.seekp(sixth);
    file.put('\x6D');  // 0xED, the sync word's first byte, with its top bit flipped
  }
  const std::string damaged = ws::test::ReadFileText(state);
  const int64_t sixth_bytes = 4 + 8 + 8 + 4 + 4 + int64_t(events[5].channel.size() + events[5].data.size());

  Bus bus(url);
  ASSERT_TRUE(bus.lcm.good());
  Running calibrate({"stereo-calibrate", "--in-url", url, "--out-url", url, "--log-dir", dir, "--state", state,
                     "--model", "poly6"},
                    &bus);
  ASSERT_TRUE(bus.Until(10, [&] { return bus.pid != 0 && !bus.statuses.empty(); }))
      << "no status from stereo-calibrate";
  EXPECT_EQ(bus.statuses.front().views_left, 29);
  const std::string said = "was damaged (bad sync word at byte " + std::to_string(sixth) +
                           ") and is kept as '" + dir + "/views-damaged-";
  const std::string counted = "intact events recovered: 29 (29 views restored); events lost: 1 (" +
                              std::to_string(sixth_bytes) + " of " + std::to_string(damaged.size()) + " bytes)";
  ASSERT_TRUE(bus.Until(5, [&] { return bus.last_error.find(counted) != std::string::npos; }))
      << "PROCESS_STATUS last_error: " << bus.last_error;
  EXPECT_NE(bus.last_error.find(said), std::string::npos) << bus.last_error;

  // The archive: the damaged file's bytes, unchanged.
  std::vector<std::string> archives;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    if (entry.path().filename().string().rfind("views-damaged-", 0) == 0) archives.push_back(entry.path());
  ASSERT_EQ(archives.size(), 1u);
  EXPECT_EQ(ws::test::ReadFileText(archives[0]), damaged);
  EXPECT_NE(bus.last_error.find(archives[0]), std::string::npos) << bus.last_error;
  const std::string log = ws::test::ReadFileText(dir + "/stereo-calibrate.log");
  EXPECT_NE(log.find(counted), std::string::npos) << log;
  EXPECT_NE(log.find(archives[0]), std::string::npos) << log;

  // The session goes on in the recovered file: a new view is appended to it.
  const widestereo::stereo_corners_t new_view = CornersMessage(rig, 30);
  bus.lcm.publish(ws::channel::kStereoCorners, &new_view);
  ASSERT_TRUE(bus.Until(5, [&] { return bus.statuses.back().views_left == 30; }))
      << "views_left " << bus.statuses.back().views_left;
  calibrate.Stop(SIGINT);
  EXPECT_EQ(calibrate.result.exit_code, 0) << calibrate.result.output;
  const ws::LcmLogScan scan = ws::ScanLcmLog(state);
  EXPECT_TRUE(scan.complete()) << scan.problem;
  const auto views = ws::test::Messages<widestereo::stereo_corners_t>(ws::test::ReadLog(state),
                                                                      ws::channel::kStereoCorners);
  ASSERT_EQ(views.size(), 30u);
  EXPECT_EQ(views[4].frame_id, 4);
  EXPECT_EQ(views[5].frame_id, 6);  // the damaged 6th event is the one lost
  EXPECT_EQ(views[29].frame_id, 30);
}

// The disk fills under the views file (a file size limit stands in for it:
// EFBIG where ENOSPC would be). Under --quiet the terminal says so once,
// with the count of the views not saved after it when the process stops;
// a restart recovers every view on disk.
TEST(StereoCalibrateLive, AViewsFileThatCannotBeWrittenIsSaidUnderQuietAndARestartRecovers) {
  const std::string dir = ws::test::TempDir("calibrate-views-full");
  const std::string url = ws::test::UniqueUdpmUrl(7);
  const std::string state = dir + "/views.lcmlog";
  SyntheticRigOptions options = BarrelRig();
  options.views = 16;
  const SyntheticRig rig = MakeSyntheticRig(options);
  std::vector<ws::test::LogEvent> events;
  for (int v = 0; v < 10; ++v) events.push_back(ws::test::Event(ws::channel::kStereoCorners, CornersMessage(rig, v)));
  ws::test::WriteLog(state, events);
  const std::vector<std::string> argv = {"stereo-calibrate", "--in-url", url, "--out-url", url, "--log-dir", dir,
                                         "--state", state, "--model", "poly6", "--quiet"};
  Bus bus(url);
  ASSERT_TRUE(bus.lcm.good());
  {
    rlimit before;
    ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &before), 0);
    const auto handler = std::signal(SIGXFSZ, SIG_IGN);  // inherited: the write fails instead
    rlimit full = before;
    full.rlim_cur = std::filesystem::file_size(state) + 100;
    ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &full), 0);
    Running calibrate(argv, &bus);
    const bool started = bus.Until(10, [&] { return bus.pid != 0 && !bus.statuses.empty(); });
    setrlimit(RLIMIT_FSIZE, &before);  // the child keeps its own
    std::signal(SIGXFSZ, handler);
    ASSERT_TRUE(started) << "no status from stereo-calibrate";
    for (int v = 10; v < 16; ++v) {
      const widestereo::stereo_corners_t msg = CornersMessage(rig, v);
      bus.lcm.publish(ws::channel::kStereoCorners, &msg);
    }
    ASSERT_TRUE(bus.Until(10, [&] { return bus.statuses.back().views_left == 16; }))
        << "views_left " << bus.statuses.back().views_left;
    calibrate.Stop(SIGINT);
    EXPECT_EQ(calibrate.result.exit_code, 0) << calibrate.result.output;
    const std::string& terminal = calibrate.result.output;
    const std::string said = "could not save the view to " + state;
    const std::string line = "stereo-calibrate: " + said + "\n";
    ASSERT_NE(terminal.find(line), std::string::npos) << terminal;
    EXPECT_EQ(terminal.find(line, terminal.find(line) + 1), std::string::npos) << "said once:\n" << terminal;
    EXPECT_NE(terminal.find("5 lines like '" + said + "' not shown"), std::string::npos) << terminal;
  }
  bus.statuses.clear();
  bus.pid = 0;
  Running restarted(argv, &bus);
  ASSERT_TRUE(bus.Until(10, [&] { return bus.pid != 0 && !bus.statuses.empty(); }))
      << "no status from the restarted stereo-calibrate";
  EXPECT_EQ(bus.statuses.front().views_left, 10);
  restarted.Stop(SIGINT);
  EXPECT_EQ(restarted.result.exit_code, 0) << restarted.result.output;
  EXPECT_NE(restarted.result.output.find("intact events recovered: 10 (10 views restored)"), std::string::npos)
      << restarted.result.output;
}

}  // namespace
