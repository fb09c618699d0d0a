// --nice lowers the priority of the thread that applies it and of the
// threads it starts afterwards, and of no other.
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <stdexcept>
#include <thread>

#include "runtime/niceness_option.h"

namespace {

int OwnNiceness() { return getpriority(PRIO_PROCESS, 0); }

TEST(NicenessOption, LowersTheThreadAndTheThreadsItStarts) {
  const int before = OwnNiceness();
  ASSERT_LT(before, 19) << "the test runs at the lowest priority already";
  const int target = std::min(19, before + 3);
  int applied = -100, inherited = -100;
  std::thread stage([&] {
    ws::ApplyNiceness(target);
    applied = OwnNiceness();
    std::thread worker([&] { inherited = OwnNiceness(); });
    worker.join();
  });
  stage.join();
  EXPECT_EQ(applied, target);
  EXPECT_EQ(inherited, target);
  EXPECT_EQ(OwnNiceness(), before);  // the other threads keep theirs
}

TEST(NicenessOption, ZeroLeavesThePriority) {
  int niceness = -100;
  std::thread stage([&] {
    setpriority(PRIO_PROCESS, 0, std::min(19, OwnNiceness() + 2));
    const int lowered = OwnNiceness();
    ws::ApplyNiceness(0);
    niceness = OwnNiceness() - lowered;
  });
  stage.join();
  EXPECT_EQ(niceness, 0);
}

TEST(NicenessOption, RaisingThePriorityBackIsRefusedWithoutPrivilege) {
  std::string error;
  bool refused = false;
  std::thread stage([&] {
    ws::ApplyNiceness(19);
    try {
      ws::ApplyNiceness(1);
    } catch (const std::runtime_error& e) {
      refused = true;
      error = e.what();
    }
  });
  stage.join();
  if (!refused) GTEST_SKIP() << "this user may raise priorities (root or RLIMIT_NICE)";
  EXPECT_NE(error.find("--nice 1: "), std::string::npos) << error;
}

TEST(NicenessOption, TheOptionTakesZeroToNineteen) {
  for (const char* value : {"0", "5", "19"}) {
    CLI::App app;
    int niceness = -1;
    ws::AddNicenessOption(app, niceness);
    const char* argv[] = {"test", "--nice", value};
    EXPECT_NO_THROW(app.parse(3, const_cast<char**>(argv))) << value;
    EXPECT_EQ(niceness, std::stoi(value));
  }
  for (const char* value : {"-1", "20"}) {
    CLI::App app;
    int niceness = -1;
    ws::AddNicenessOption(app, niceness);
    const char* argv[] = {"test", "--nice", value};
    EXPECT_THROW(app.parse(3, const_cast<char**>(argv)), CLI::ValidationError) << value;
  }
}

}  // namespace
