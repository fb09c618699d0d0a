// What stereo-calibrate keeps between solves: accepted views, near
// duplicates skipped, the coverage and hint, and the state file that brings
// the views back after a crash, even one in the middle of a write.
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <csignal>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>

#include "calib/evaluate/coverage.h"
#include "calib/node/calibration_session.h"
#include "calib/node/corners_message.h"
#include "calib/node/preview_solve.h"
#include "calib/solver/corner_noise.h"
#include "calib_test_rigs.h"
#include "lcm_io/decode.h"
#include "test_support.h"

namespace {

using namespace ws::calib;
using namespace ws::calib::test;

widestereo::stereo_corners_t Message(const SyntheticRig& rig, int v, const std::string& board) {
  widestereo::stereo_corners_t msg{};
  msg.utime = 1000 * v;
  msg.frame_id = v;
  msg.left = ToCornersMessage(rig.data.left.views[v], board, 1280, 960);
  msg.right = ToCornersMessage(rig.data.right.views[v], board, 1280, 960);
  return msg;
}

class CalibSession : public ::testing::Test {
 protected:
  void SetUp() override {
    SyntheticRigOptions options = BarrelRig();
    options.views = 8;
    rig = MakeSyntheticRig(options);
  }
  SyntheticRig rig;
  const std::string board = "chessboard:12x9:0.04";
};

// A session keeps at most max_views views: a flood cannot grow it.
// The preview solves an angle model where one is asked (the defaults list
// bspline first, which cannot image a lens past 90 degrees), else the first.
TEST(PreviewModel, TheFirstAngleModelElseTheFirstAsked) {
  using ws::ModelKind;
  EXPECT_EQ(PreviewModel({ModelKind::kBspline, ModelKind::kPoly6, ModelKind::kPoly12, ModelKind::kKb4,
                          ModelKind::kBsplineTheta}),
            ModelKind::kKb4);
  EXPECT_EQ(PreviewModel({ModelKind::kBsplineTheta, ModelKind::kKb4}), ModelKind::kBsplineTheta);
  EXPECT_EQ(PreviewModel({ModelKind::kPoly6, ModelKind::kBspline}), ModelKind::kPoly6);
}

TEST_F(CalibSession, ViewsBeyondTheMaximumAreRejectedSayingWhy) {
  SessionOptions options;
  options.max_views = 3;
  CalibrationSession session(options);
  for (int v = 0; v < 3; ++v) EXPECT_EQ(session.Add(Message(rig, v, board)), CalibrationSession::Outcome::kAccepted);
  std::string why;
  EXPECT_EQ(session.Add(Message(rig, 3, board), &why), CalibrationSession::Outcome::kRejected);
  EXPECT_EQ(why, "the session holds its maximum of 3 views (--max-views); 'reset' archives them and starts again");
  EXPECT_EQ(session.views(), 3);
}

// The rig's corners carry 0.1 px of noise per coordinate; the rows of its
// barrel lens bend little between neighbours.
TEST_F(CalibSession, CornerNoiseIsMeasuredFromTheBoardsRowsAndColumns) {
  for (int v = 0; v < rig.data.size(); ++v) {
    const double noise = CornerNoise(rig.data.left.views[v]);
    EXPECT_GT(noise, 0.08) << "view " << v;
    EXPECT_LT(noise, 0.13) << "view " << v;
  }
  EXPECT_EQ(CornerNoise(BoardView()), 0.0);
}

// A board held still is detected again with new noise: a near duplicate. A
// view moved by 2 px, less than the old rule's 1.5 % of the diagonal (24 px
// here), is a view someone chose: kept.
TEST_F(CalibSession, SkipsNearDuplicatesEmptyFramesAndOtherBoards) {
  CalibrationSession session(SessionOptions{});
  EXPECT_EQ(session.Add(Message(rig, 0, board)), CalibrationSession::Outcome::kAccepted);
  std::mt19937 random(7);
  std::normal_distribution<double> noise(0.0, 0.1);
  widestereo::stereo_corners_t still = Message(rig, 0, board);
  for (auto* side : {&still.left, &still.right})
    for (auto& p : side->image_points) p[0] += noise(random), p[1] += noise(random);
  EXPECT_EQ(session.Add(still), CalibrationSession::Outcome::kDuplicate);
  widestereo::stereo_corners_t moved = Message(rig, 0, board);
  for (auto& p : moved.left.image_points) p[0] += 2.0;
  EXPECT_EQ(session.Add(moved), CalibrationSession::Outcome::kAccepted);
  widestereo::stereo_corners_t empty = Message(rig, 2, board);
  empty.left = ToCornersMessage(BoardView(), board, 1280, 960);
  empty.right = empty.left;
  EXPECT_EQ(session.Add(empty), CalibrationSession::Outcome::kNoBoard);
  std::string why;
  EXPECT_EQ(session.Add(Message(rig, 3, "chessboard:9x6:0.025"), &why),
            CalibrationSession::Outcome::kRejected);
  EXPECT_NE(why.find("differs from the board so far"), std::string::npos) << why;
  EXPECT_EQ(session.views(), 2);
  EXPECT_EQ(session.duplicates(), 1);

  const auto status = session.Status(42, "collecting", -1);
  EXPECT_EQ(status.views_left, 2);
  EXPECT_EQ(status.grid_rows, 6);
  EXPECT_EQ(status.grid_cols, 8);
  EXPECT_NE(status.hint.find("need at least 3 views per camera"), std::string::npos) << status.hint;
}

TEST_F(CalibSession, TheStateFileBringsTheViewsBackAfterACrashMidWrite) {
  const std::string state = ws::test::TempDir("calib-session") + "/views.lcmlog";
  SessionOptions options;
  options.state_path = state;
  {
    CalibrationSession session(options);
    EXPECT_EQ(session.Restore(), 0);
    for (int v = 0; v < 5; ++v) session.Add(Message(rig, v, board));
  }
  {  // a process killed while writing the next view leaves half an event
    std::ofstream(state, std::ios::app | std::ios::binary)
        << std::string("\xED\xA1\xDA\x01partial", 11);
  }
  const std::string damaged = ws::test::ReadFileText(state);
  {
    CalibrationSession session(options);
    EXPECT_EQ(session.Restore(), 5);
    // Kept, never truncated: the damaged file is archived with its bytes.
    const std::string damage = session.StateDamage();
    const size_t quote = damage.find("kept as '") + 9;
    const std::string archive = damage.substr(quote, damage.find('\'', quote) - quote);
    EXPECT_NE(archive.find("/views-damaged-"), std::string::npos) << damage;
    EXPECT_EQ(ws::test::ReadFileText(archive), damaged);
    EXPECT_NE(damage.find("intact events recovered: 5 (5 views restored); events lost: 1 (11 of " +
                          std::to_string(damaged.size()) + " bytes)"),
              std::string::npos)
        << damage;
    EXPECT_EQ(session.Add(Message(rig, 2, board)), CalibrationSession::Outcome::kDuplicate);
    EXPECT_EQ(session.Add(Message(rig, 5, board)), CalibrationSession::Outcome::kAccepted);
  }
  CalibrationSession session(options);
  EXPECT_EQ(session.Restore(), 6);
  EXPECT_EQ(session.StateDamage(), "");  // the new state file is intact
  const StereoData data = session.Data();
  ASSERT_EQ(data.size(), 6);
  EXPECT_EQ(data.left.views[5].image, rig.data.left.views[5].image);
}

// The disk fills while a view is saved (a file size limit stands in for
// it: EFBIG where ENOSPC would be): the view is accepted and the failure
// said; a restart while the disk is still full recovers every view on
// disk and starts (it once refused to).
TEST_F(CalibSession, AFullDiskIsSaidAndARestartRecoversWhatIsOnDisk) {
  const std::string state = ws::test::TempDir("calib-session-full") + "/views.lcmlog";
  SessionOptions options;
  options.state_path = state;
  rlimit before;
  ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &before), 0);
  const auto handler = std::signal(SIGXFSZ, SIG_IGN);
  auto limit = [&](rlim_t bytes) {
    rlimit small = before;
    small.rlim_cur = bytes;
    ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &small), 0);
  };
  size_t on_disk = 0;
  {
    CalibrationSession session(options);
    EXPECT_EQ(session.Restore(), 0);
    for (int v = 0; v < 3; ++v) session.Add(Message(rig, v, board));
    on_disk = std::filesystem::file_size(state);
    limit(on_disk + on_disk / 6);  // half a view more
    std::string why;
    EXPECT_EQ(session.Add(Message(rig, 3, board), &why), CalibrationSession::Outcome::kAccepted);
    EXPECT_NE(why.find("could not save the view to " + state), std::string::npos) << why;
  }
  limit(on_disk / 2);  // still full: the state cannot be written again
  {
    CalibrationSession session(options);
    EXPECT_EQ(session.Restore(), 3);
    EXPECT_NE(session.StateDamage().find("it could not be written again"), std::string::npos)
        << session.StateDamage();
  }
  setrlimit(RLIMIT_FSIZE, &before);
  std::signal(SIGXFSZ, handler);
  CalibrationSession session(options);
  EXPECT_EQ(session.Restore(), 3);  // the damage passed over again, nothing lost
}

// A state file with nothing recoverable is archived all the same, never
// deleted, and the session starts with an empty one.
TEST_F(CalibSession, AStateFileWithNothingRecoverableIsArchivedNotDeleted) {
  const std::string dir = ws::test::TempDir("calib-session-garbage");
  SessionOptions options;
  options.state_path = dir + "/views.lcmlog";
  const std::string garbage = "not an LCM log at all";
  std::ofstream(options.state_path, std::ios::binary) << garbage;
  CalibrationSession session(options);
  EXPECT_EQ(session.Restore(), 0);
  EXPECT_NE(session.StateDamage().find("intact events recovered: 0 (0 views restored); events lost: 1 (21 of 21 bytes)"),
            std::string::npos)
      << session.StateDamage();
  std::vector<std::string> archives;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    if (entry.path().filename().string().rfind("views-damaged-", 0) == 0) archives.push_back(entry.path());
  ASSERT_EQ(archives.size(), 1u);
  EXPECT_EQ(ws::test::ReadFileText(archives[0]), garbage);
  EXPECT_EQ(ws::test::ReadFileText(options.state_path), "");
  EXPECT_EQ(session.Add(Message(rig, 0, board)), CalibrationSession::Outcome::kAccepted);
  EXPECT_EQ(CalibrationSession(options).Restore(), 1);
}

// reset archives the state file under a timestamp (never truncates it) and
// restore brings the newest archive back, archiving the views of the moment
// first; without a state file the archives are kept in memory.
TEST_F(CalibSession, ResetArchivesTheViewsAndRestoreBringsThemBack) {
  const std::string dir = ws::test::TempDir("calib-session-archive");
  for (const std::string& state : {dir + "/views.lcmlog", std::string()}) {
    SCOPED_TRACE(state.empty() ? "no state file" : state);
    SessionOptions options;
    options.state_path = state;
    CalibrationSession session(options);
    session.Restore();
    EXPECT_THROW(session.RestoreLastArchive(1), std::runtime_error);  // nothing archived yet
    for (int v = 0; v < 5; ++v) session.Add(Message(rig, v, board));
    const std::string kept = ws::test::ReadFileText(state);
    const StereoData before = session.Data();

    const std::string archive = session.Reset(1764619200123456);  // 2025-12-01 20:00:00.123456 UTC
    EXPECT_EQ(session.views(), 0);
    if (!state.empty()) {
      EXPECT_EQ(archive, dir + "/views-20251201T200000.123456Z.lcmlog");
      EXPECT_EQ(ws::test::ReadFileText(archive), kept);
      EXPECT_EQ(CalibrationSession(options).Restore(), 0);  // the state file starts empty
    }
    EXPECT_EQ(session.Reset(1764619201000000), "");  // no view: nothing archived

    session.Add(Message(rig, 7, board));
    EXPECT_EQ(session.RestoreLastArchive(1764619202000000), state.empty() ? "memory" : archive);
    const StereoData after = session.Data();
    ASSERT_EQ(after.size(), 5);
    for (int v = 0; v < 5; ++v) EXPECT_EQ(after.left.views[v].image, before.left.views[v].image);
    if (!state.empty()) {
      EXPECT_EQ(ws::test::ReadFileText(state), kept);
      EXPECT_EQ(CalibrationSession(options).Restore(), 5);
    }
    // The one view collected after the reset was archived, not lost.
    session.RestoreLastArchive(1764619203000000);
    EXPECT_EQ(session.views(), 1);
  }
}

// A user's removal takes one view out of the session and of its state file
// (a restart does not bring it back), keeps it in the removed-views file,
// and leaves every other view as it was; an unknown or ambiguous view is
// refused and changes nothing.
TEST_F(CalibSession, RemoveTakesOneViewOutAndARestartDoesNotBringItBack) {
  const std::string dir = ws::test::TempDir("calib-session-remove");
  SessionOptions options;
  options.state_path = dir + "/views.lcmlog";
  CalibrationSession session(options);
  session.Restore();
  for (int v = 0; v < 5; ++v) ASSERT_EQ(session.Add(Message(rig, v, board)), CalibrationSession::Outcome::kAccepted);
  auto again = Message(rig, 5, board);
  again.frame_id = 1;  // stereo-capture started again: frame 1 a second time
  ASSERT_EQ(session.Add(again), CalibrationSession::Outcome::kAccepted);
  const std::string before = ws::test::ReadFileText(options.state_path);

  EXPECT_THROW(session.Remove(9, std::nullopt), std::invalid_argument);
  try {
    session.Remove(1, std::nullopt);
    ADD_FAILURE() << "an ambiguous frame id was taken";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "2 views of frame 1: name its utime too");
  }
  EXPECT_EQ(ws::test::ReadFileText(options.state_path), before) << "a refusal changed the state file";
  EXPECT_EQ(session.views(), 6);

  EXPECT_EQ(session.Remove(2, 2000), dir + "/views-removed.lcmlog");
  EXPECT_EQ(session.Remove(1, 5000), dir + "/views-removed.lcmlog");
  std::vector<int64_t> frames, utimes;
  session.Data(&frames, &utimes);
  EXPECT_EQ(frames, (std::vector<int64_t>{0, 1, 3, 4}));
  EXPECT_EQ(utimes, (std::vector<int64_t>{0, 1000, 3000, 4000}));
  CalibrationSession kept{SessionOptions{}};
  for (int v : {0, 1, 3, 4}) kept.Add(Message(rig, v, board));
  EXPECT_EQ(session.Status(0, "collecting", -1).coverage_left, kept.Status(0, "collecting", -1).coverage_left)
      << "the coverage is that of the views kept";
  const auto views = session.Views(7);
  ASSERT_EQ(views.nviews, 4);
  EXPECT_EQ(views.views[2].frame_id, 3);
  EXPECT_EQ(views.views[2].left_corners, Message(rig, 3, board).left.n);
  EXPECT_LT(views.views[2].left_rms, 0) << "no solve yet";
  EXPECT_EQ(views.image_width[0], 1280);

  // Restarted, the session has the four views; the two removed are kept aside.
  CalibrationSession restarted(options);
  EXPECT_EQ(restarted.Restore(), 4);
  frames.clear();
  restarted.Data(&frames);
  EXPECT_EQ(frames, (std::vector<int64_t>{0, 1, 3, 4}));
  std::vector<int64_t> removed;
  for (const auto& event : ws::test::ReadLog(dir + "/views-removed.lcmlog"))
    removed.push_back(ws::DecodeMessage<widestereo::stereo_corners_t>(event.data.data(), int(event.data.size())).utime);
  EXPECT_EQ(removed, (std::vector<int64_t>{2000, 5000}));
  // A view added after a removal is saved after the others.
  EXPECT_EQ(restarted.Add(Message(rig, 6, board)), CalibrationSession::Outcome::kAccepted);
  EXPECT_EQ(CalibrationSession(options).Restore(), 5);
}

}  // namespace

namespace {

// Found by tests/fuzz (UBSan): a corner at 1e244 px was converted to int.
TEST(Coverage, OnlyCornersInsideTheImageAreCounted) {
  ws::calib::CoverageGrid grid(6, 8);
  ws::calib::BoardView view;
  const double inf = std::numeric_limits<double>::infinity();
  view.image = {Eigen::Vector2d(1e244, 10),        Eigen::Vector2d(-1e244, 10),     Eigen::Vector2d(10, inf),
                Eigen::Vector2d(std::nan(""), 10), Eigen::Vector2d(-0.5, -0.5),     Eigen::Vector2d(1279.4, 959.4),
                Eigen::Vector2d(1279.5, 10)};
  grid.Add(view, 1280, 960);
  std::vector<int> expected(48, 0);
  expected.front() = expected.back() = 1;
  EXPECT_EQ(grid.count, expected);
}

}  // namespace
