// The shared command line: YAML config files, flags overriding them, errors.
#include <gtest/gtest.h>

#include <fstream>
#include <iostream>
#include <sstream>

#include "runtime/process_cli.h"
#include "test_support.h"

namespace {

struct Parsed {
  std::optional<int> exit_code;
  std::string board = "default";
  double rate = 0;
  std::vector<int> ids;
  int workers = 1;
  std::string in_url;
  std::string errors;  // what ProcessCli said on stderr
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
  cli.app().add_option("--workers", p.workers)->check(CLI::Range(1, 256));
  std::ostringstream errors;
  std::streambuf* stderr_buffer = std::cerr.rdbuf(errors.rdbuf());
  p.exit_code = cli.Parse(int(argv.size()), argv.data());
  std::cerr.rdbuf(stderr_buffer);
  p.errors = errors.str();
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

TEST(ProcessCli, ConfigErrorsNameTheFileTheKeyAndTheReason) {
  auto said = [](const std::string& yaml) { return Parse({}, yaml).errors; };
  EXPECT_NE(said("bored: 1\n").find("c.yaml: unknown option 'bored'"), std::string::npos) << said("bored: 1\n");
  EXPECT_NE(said("rate: fast\n").find("c.yaml: Could not convert: --rate = fast"), std::string::npos)
      << said("rate: fast\n");
  EXPECT_NE(said("workers: 0\n").find("c.yaml: --workers: Value 0 not in range 1 to 256"), std::string::npos)
      << said("workers: 0\n");
  EXPECT_NE(said("board: {a: 1}\n").find("c.yaml: config key 'board' (line 1) must be a scalar"),
            std::string::npos)
      << said("board: {a: 1}\n");
  EXPECT_NE(said("rate: [1, 2\n").find("c.yaml: config is not valid YAML"), std::string::npos)
      << said("rate: [1, 2\n");
  const std::string missing = Parse({"--config", "/nonexistent.yaml"}).errors;
  EXPECT_NE(missing.find("/nonexistent.yaml"), std::string::npos) << missing;
}

TEST(ProcessCli, HelpExitsZero) { EXPECT_EQ(Parse({"--help"}).exit_code, 0); }

}  // namespace
