// The recording as the page shows it: a one-file log stopped at its cap, and
// a rolling one (lcm-logger --rotate: <log>.0 the newest) that is never
// stopped but, once all its files are there, says how long it spans.
#include "view/recording_watch.h"

#include <gtest/gtest.h>
#include <fcntl.h>
#include <sys/stat.h>

#include <fstream>
#include <string>

#include "test_support.h"

namespace {

using ws::view::RecordingWatch;

// A file of `bytes` bytes last written at `mtime_s` (seconds since the epoch).
void Write(const std::string& path, size_t bytes, int64_t mtime_s) {
  std::ofstream(path, std::ios::binary) << std::string(bytes, 'x');
  const timespec times[2] = {{mtime_s, 0}, {mtime_s, 0}};
  ASSERT_EQ(utimensat(AT_FDCWD, path.c_str(), times, 0), 0) << path;
}

TEST(RecordingWatch, OneFileIsStoppedAtItsCap) {
  const std::string log = ws::test::TempDir("recording-one") + "/run.lcmlog";
  RecordingWatch watch(log, 1000);
  EXPECT_FALSE(watch.Check(1));
  EXPECT_TRUE(watch.Json()["mb"].is_null()) << "no file yet";
  Write(log, 999, 100);
  EXPECT_FALSE(watch.Check(2));
  Write(log, 1000, 101);
  EXPECT_TRUE(watch.Check(3));
  EXPECT_FALSE(watch.Check(4)) << "said once";
  EXPECT_EQ(watch.StateText(), "recording stopped");
  EXPECT_NE(watch.StoppedText().find("reached its cap of 0.001 MB"), std::string::npos) << watch.StoppedText();
  EXPECT_FALSE(watch.Json()["rolling"].get<bool>());
}

TEST(RecordingWatch, ARollingOneIsNeverStoppedAndSaysTheTimeItSpans) {
  const std::string log = ws::test::TempDir("recording-rolling") + "/run.lcmlog";
  RecordingWatch watch(log, 4000, 4);  // four files of about 1000 bytes
  // Three files, begun at 1000 s, 1060 s and 1120 s: not full, nothing deleted yet.
  Write(log + ".2", 1000, 1060);
  Write(log + ".1", 1000, 1120);
  Write(log + ".0", 500, 1150);
  EXPECT_FALSE(watch.Check(1150000000));
  EXPECT_EQ(watch.StateText(), "");
  EXPECT_DOUBLE_EQ(watch.Json()["mb"].get<double>(), 0.0025);
  EXPECT_TRUE(watch.Json()["window_s"].is_null());
  // A fourth: full, the oldest deleted from the next file on. Files of 60 s
  // each; the oldest begun a file's length before its last write (940 s).
  Write(log + ".3", 1000, 1000);
  EXPECT_TRUE(watch.Check(1150000000));
  const auto json = watch.Json();
  EXPECT_TRUE(json["rolling"].get<bool>() && json["capped"].get<bool>());
  EXPECT_EQ(json["files"], 4);
  EXPECT_DOUBLE_EQ(json["window_s"].get<double>(), 1150 - 940);
  EXPECT_EQ(watch.StateText(), "recording rolling: the last 3.5 min");
  EXPECT_EQ(watch.StoppedText(), "") << "a rolling recording does not stop";
  EXPECT_EQ(json["path"], log + ".0");
}

}  // namespace
