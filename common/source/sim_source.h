// stereo-capture's simulator source: --source sim:CONFIG.yaml[?truth=FILE]
//
// Renders the frames of a simulator config (sim_config.h) in order, one
// stereo pair per Next(), and ends after the last (or starts again, with
// loop). Opening it writes the ground truth (ground_truth.h) of every frame
// to, in order of preference: the spec's ?truth=FILE, the config's `truth:`
// field, or logs/sim/<config name>.truth.yaml under the working folder
// (beside the process's default text log; git ignores it). Pair labels name the frame:
// "sim frame 3/35 (board, aimed at right)".
#pragma once

#include <memory>
#include <string>

#include "sim/simulator.h"
#include "source/stereo_source.h"

namespace ws {

class SimSource : public StereoSource {
 public:
  // Plans the frames (throws SimConfigError) and writes the truth file when
  // truth_path is not empty (throws std::runtime_error when it cannot be written).
  SimSource(SimConfig config, bool loop, const std::string& truth_path);
  // Over a simulator built in code; writes nothing.
  SimSource(std::shared_ptr<const Simulator> simulator, bool loop);

  std::optional<StereoPair> Next() override;
  std::map<std::string, SourceCounts> Counters() const override;

  const Simulator& simulator() const { return *simulator_; }
  const std::string& truth_path() const { return truth_path_; }

 private:
  std::shared_ptr<const Simulator> simulator_;
  bool loop_;
  std::string name_;
  std::string truth_path_;
  int next_ = 0;
  int64_t rendered_ = 0;
};

// logs/sim/<config file name without extension>.truth.yaml
std::string DefaultSimTruthPath(const std::string& config_path);

// The source for the text after "sim:": CONFIG.yaml, optionally followed by
// ?truth=FILE. Throws std::invalid_argument for a malformed spec.
std::unique_ptr<SimSource> MakeSimSource(const std::string& spec, bool loop);

}  // namespace ws
