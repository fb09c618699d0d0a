// The flat YAML config of every process (--config FILE, runtime/yaml_config.h)
// read through ProcessCli, with an option of each kind the processes declare.
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "fuzz_support.h"
#include "runtime/process_cli.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = ws::fuzz::WriteInputFile(data, size, ".yaml");
  ws::ProcessCli cli("fuzz-config", "Reads a fuzzed --config file.");
  // Options of each kind, named as in config/stereo-capture.yaml and stereo-detect.yaml.
  std::string source, board, detector = "classic", compression = "none";
  int workers = 2, max_in_flight = 4, jpeg_quality = 95;
  double rate = 5;
  bool loop = false;
  std::vector<std::string> append;
  auto& app = cli.app();
  app.add_option("--source", source);
  app.add_option("--board", board);
  app.add_option("--chessboard-detector", detector)->check(CLI::IsMember({"sb", "classic"}));
  app.add_option("--compression", compression)->check(CLI::IsMember({"none", "jpeg", "png"}));
  app.add_option("--workers", workers)->check(CLI::Range(1, 256));
  app.add_option("--max-in-flight", max_in_flight)->check(CLI::Range(1, 1024));
  app.add_option("--jpeg-quality", jpeg_quality)->check(CLI::Range(1, 100));
  app.add_option("--rate", rate);
  app.add_flag("--loop", loop);
  app.add_option("--append", append);
  std::string argv0 = "fuzz-config", flag = "--config";
  char* argv[] = {argv0.data(), flag.data(), const_cast<char*>(path.c_str()), nullptr};
  // ProcessCli says on stderr why a file is rejected; keep the fuzzer's output readable.
  std::ostringstream discard;
  std::streambuf* stderr_buffer = std::cerr.rdbuf(discard.rdbuf());
  cli.Parse(3, argv);
  std::cerr.rdbuf(stderr_buffer);
  return 0;
}
