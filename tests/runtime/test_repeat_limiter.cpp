// RepeatLimiter and TextLog: an error recurring once a frame is written once
// a period, with the count of those not shown; nothing is lost from the count.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "runtime/repeat_limiter.h"
#include "runtime/text_log.h"
#include "test_support.h"

namespace {

constexpr int64_t kSecond = 1'000'000;

TEST(RepeatLimiter, LinesDifferingInTheirNumbersAreOneShape) {
  EXPECT_EQ(ws::RepeatLimiter::Shape("frame 17 not used: 300 views"), "frame # not used: # views");
  EXPECT_EQ(ws::RepeatLimiter::Shape("frame 18 not used: 300 views"), "frame # not used: # views");
  EXPECT_NE(ws::RepeatLimiter::Shape("frame 18 not used: board 'a'"), "frame # not used: # views");
}

TEST(RepeatLimiter, AShapeIsWrittenOnceAPeriodWithTheCountOfTheRest) {
  ws::RepeatLimiter limiter(10 * kSecond);
  std::string note;
  int written = 0;
  // 30 Hz for 25 s: written at 0, 10 and 20 s.
  for (int frame = 0; frame < 750; ++frame) {
    if (!limiter.Admit("frame " + std::to_string(frame) + " not used", frame * kSecond / 30, &note)) continue;
    ++written;
    if (frame == 0) {
      EXPECT_EQ(note, "");
    } else if (frame == 300) {
      EXPECT_EQ(note, " (and 299 like it in the last 10 s, not shown)");
    }
  }
  EXPECT_EQ(written, 3);
  EXPECT_TRUE(limiter.Admit("another line", 25 * kSecond, &note));
  const auto untold = limiter.Flush();
  ASSERT_EQ(untold.size(), 1u);
  EXPECT_EQ(untold[0], "149 lines like 'frame 749 not used' not shown");
  EXPECT_TRUE(limiter.Flush().empty());
}

TEST(RepeatLimiter, TextVariedByAPeerSharesOneSlotOnceTheTableIsFull) {
  ws::RepeatLimiter limiter(10 * kSecond);
  std::string note;
  int written = 0;
  for (size_t i = 0; i < 3 * ws::RepeatLimiter::kMaxShapes; ++i) {
    std::string name;
    for (size_t n = i; n > 0 || name.empty(); n /= 26) name += char('a' + n % 26);
    written += limiter.Admit("board '" + name + "' differs", kSecond, &note);
  }
  EXPECT_EQ(written, int(ws::RepeatLimiter::kMaxShapes) + 1);
  // Past the period, the idle shapes make room again.
  EXPECT_TRUE(limiter.Admit("board 'new' differs", 12 * kSecond, &note));
}

TEST(TextLog, AFloodOfOneRecurringShapeIsOneLineAndACount) {
  const std::string dir = ws::test::TempDir("text-log-flood");
  {
    ws::TextLog log("flood", dir, true);
    for (int frame = 0; frame < 5000; ++frame) log.Recurring("frame " + std::to_string(frame) + " not used");
    log.Info("done");
  }
  std::ifstream file(dir + "/flood.log");
  std::string line, text;
  int lines = 0;
  while (std::getline(file, line)) ++lines, text += line + '\n';
  EXPECT_EQ(lines, 3) << text;
  EXPECT_NE(text.find("error frame 0 not used"), std::string::npos) << text;
  EXPECT_NE(text.find("4999 lines like 'frame 4999 not used' not shown"), std::string::npos) << text;
}

// What a folder says of each of its files is bounded by the folder: every
// file is named.
TEST(TextLog, ErrorsAreEveryOneWritten) {
  const std::string dir = ws::test::TempDir("text-log-errors");
  {
    ws::TextLog log("folder", dir, true);
    for (int image = 0; image < 40; ++image) log.Error("left" + std::to_string(image) + ".png: no board: left out");
  }
  std::ifstream file(dir + "/folder.log");
  std::string line;
  int lines = 0;
  while (std::getline(file, line)) lines += line.find(": no board: left out") != std::string::npos;
  EXPECT_EQ(lines, 40);
}

}  // namespace
