// The shared command line: YAML config files, flags overriding them, errors.
#include <gtest/gtest.h>

#include <fstream>

#include "runtime/process_cli.h"
#include "test_support.h"

namespace {

struct Parsed {
  std::optional<int> exit_code;
  std::string board = "default";
  double rate = 0;
  std::vector<int> ids;
  std::string in_url;
};

Parsed Parse(std::vector<std::string> args, const std::string& yaml = "") {
  const std::string dir = ws::test::TempDir("cli");
  if (!yaml.empty()) {
    std::ofstream(dir + "/c.yaml") << yaml;
    args.insert(args.begin(), {"--config", dir + "/c.yaml"});
  }
  args.insert(args.begin(), "stereo-test");
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  ws::ProcessCli cli("stereo-test", "test");
  Parsed p;
  cli.app().add_option("--board", p.board);
  cli.app().add_option("--rate", p.rate);
  cli.app().add_option("--ids", p.ids);
  p.exit_code = cli.Parse(int(argv.size()), argv.data());
  p.in_url = cli.options().in_url;
  return p;
}

TEST(ProcessCli, ConfigFileSetsOptionsAndFlagsOverrideIt) {
  const std::string yaml = "board: chessboard:9x6:0.025\nrate: 2.5\nids: [1, 2, 3]\n"
                           "in-url: \"file:///tmp/x.lcmlog?speed=0\"\n";
  Parsed p = Parse({}, yaml);
  ASSERT_FALSE(p.exit_code);
  EXPECT_EQ(p.board, "chessboard:9x6:0.025");
  EXPECT_DOUBLE_EQ(p.rate, 2.5);
  EXPECT_EQ(p.ids, (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(p.in_url, "file:///tmp/x.lcmlog?speed=0");
  p = Parse({"--rate", "7"}, yaml);
  EXPECT_DOUBLE_EQ(p.rate, 7);
  EXPECT_EQ(p.board, "chessboard:9x6:0.025");
}

TEST(ProcessCli, UnknownKeysBadValuesAndBadYamlAreErrors) {
  EXPECT_NE(Parse({}, "bored: 1\n").exit_code.value_or(0), 0);
  EXPECT_NE(Parse({}, "rate: fast\n").exit_code.value_or(0), 0);
  EXPECT_NE(Parse({}, "rate: [1, 2\n").exit_code.value_or(0), 0);
  EXPECT_NE(Parse({"--no-such-flag"}).exit_code.value_or(0), 0);
  EXPECT_NE(Parse({"--config", "/nonexistent.yaml"}).exit_code.value_or(0), 0);
}

TEST(ProcessCli, HelpExitsZero) { EXPECT_EQ(Parse({"--help"}).exit_code, 0); }

}  // namespace
