// The options every widestereo process shares (process_cli.h parses them).
// A header of their own so that the many files that need only the options
// (through process.h) do not compile CLI11: each file that includes it
// builds CLI11's global validators, several seconds of compile time apiece
// (calib/node/calibrate_node.cpp went from 24 s to 7 s on a loaded core).
#pragma once

#include <string>

namespace ws {

struct ProcessOptions {
  std::string name;
  std::string config_file;
  std::string in_url;   // "" = LCM's default (LCM_DEFAULT_URL or udpm multicast)
  std::string out_url;  // "" with a file:// input: a log file (batch_out), never the live bus
  // A batch run (a file:// input, or `batch`: files read by the process
  // itself) without --out-url writes its output to an LCM log file,
  // `batch_out`; "" = <log_dir>/<name>.lcmlog.
  bool batch = false;
  std::string batch_out;
  // With it, the batch output log goes to a temporary name beside
  // `batch_out` and is put in place only when the process ends with exit
  // code 0 (Process::DiscardBatchOutput aside): a failed run leaves the old
  // log whole, and none of its own.
  bool batch_out_when_done = false;
  std::string log_dir = "logs";
  std::string key_file;  // "" = no rig key: nothing signed or checked
  // How far ahead of this process's clock a signed message may be dated:
  // a sender's clock that runs fast by more is refused, so that "signed
  // before this process started" also holds for it (docs/security.md).
  double max_clock_skew_s = 2;
  bool quiet = false;
};

}  // namespace ws
