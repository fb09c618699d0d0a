// LibraryLog: what Ceres says through glog goes into the process's log file,
// not onto the terminal in glog's own format.
#include <glog/logging.h>
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "runtime/library_log.h"
#include "runtime/text_log.h"
#include "test_support.h"

namespace {

struct Said {
  std::string terminal, file;
};

// What the terminal and process `name`'s log file get while `say` runs
// with a LibraryLog on that log.
Said WithLibraryLog(const std::string& name, bool quiet, const std::function<void()>& say) {
  std::string path;
  testing::internal::CaptureStderr();
  {
    ws::TextLog log(name, ws::test::TempDir(name), quiet);
    path = log.path();
    ws::LibraryLog library(log);
    say();
  }  // the log file closed
  const std::string terminal = testing::internal::GetCapturedStderr();
  return {terminal, ws::test::ReadFileText(path)};
}

TEST(LibraryLog, WarningsBecomeDetailLinesOfTheLogFileAndReachNoTerminal) {
  const Said said = WithLibraryLog("glog-warning", /*quiet=*/false, [] {
    LOG(WARNING) << "Linear solver failure. Failed to compute a step";
    LOG(INFO) << "an inner iteration";
  });
  EXPECT_EQ(said.terminal.find("Linear solver failure"), std::string::npos) << said.terminal;
  EXPECT_EQ(said.terminal.find("an inner iteration"), std::string::npos) << said.terminal;
  EXPECT_NE(said.file.find(" detail (test_library_log.cpp:"), std::string::npos) << said.file;
  EXPECT_NE(said.file.find("Linear solver failure. Failed to compute a step"), std::string::npos);
  EXPECT_NE(said.file.find("an inner iteration"), std::string::npos);
}

TEST(LibraryLog, ErrorsAreTheProcesssErrors) {
  const Said said = WithLibraryLog("glog-error", /*quiet=*/true,
                                   [] { LOG(ERROR) << "the problem is not well formed"; });
  EXPECT_NE(said.terminal.find("glog-error: (test_library_log.cpp:"), std::string::npos) << said.terminal;
  EXPECT_EQ(said.terminal.find("E20"), std::string::npos) << "glog's own format: " << said.terminal;
  EXPECT_NE(said.file.find(" error (test_library_log.cpp:"), std::string::npos) << said.file;
}

}  // namespace
