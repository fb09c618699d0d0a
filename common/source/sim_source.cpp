#include "source/sim_source.h"

#include <filesystem>
#include <stdexcept>

namespace ws {

SimSource::SimSource(SimConfig config, bool loop, const std::string& truth_path)
    : simulator_(std::make_shared<const Simulator>(std::move(config))),
      loop_(loop),
      name_("sim:" + simulator_->config().source),
      truth_path_(truth_path) {
  if (simulator_->frame_count() == 0) throw SimConfigError(simulator_->config().source + ": the scene has no frames");
  if (!truth_path_.empty()) WriteSimTruth(truth_path_, simulator_->Truth());
}

SimSource::SimSource(std::shared_ptr<const Simulator> simulator, bool loop)
    : simulator_(std::move(simulator)), loop_(loop), name_("sim:" + simulator_->config().source) {}

std::optional<StereoPair> SimSource::Next() {
  if (next_ == simulator_->frame_count()) {
    if (!loop_ || next_ == 0) return std::nullopt;
    next_ = 0;
  }
  const int frame = next_++;
  StereoPair pair;
  std::tie(pair.left, pair.right) = simulator_->Render(frame);
  const SimFrame& f = simulator_->frames()[frame];
  pair.label = "sim frame " + std::to_string(frame) + "/" + std::to_string(simulator_->frame_count()) +
               (f.kind == SimFrame::Kind::wall   ? std::string(" (wall)")
                : f.kind == SimFrame::Kind::room ? std::string(" (room)")
                                                 : std::string(" (board, aimed at ") +
                                                       (f.target_camera == 0 ? "left)" : "right)"));
  ++rendered_;
  return pair;
}

std::map<std::string, SourceCounts> SimSource::Counters() const { return {{name_, {rendered_, 0, 0}}}; }

std::string DefaultSimTruthPath(const std::string& config_path) {
  return (std::filesystem::path("logs") / "sim" / (std::filesystem::path(config_path).stem().string() + ".truth.yaml"))
      .string();
}

std::unique_ptr<SimSource> MakeSimSource(const std::string& spec, bool loop) {
  const size_t query = spec.find('?');
  const std::string config = spec.substr(0, query);
  std::string truth;
  if (query != std::string::npos) {
    const std::string option = spec.substr(query + 1);
    if (option.rfind("truth=", 0) != 0 || option.size() == 6)
      throw std::invalid_argument("sim: takes CONFIG.yaml or CONFIG.yaml?truth=FILE, not 'sim:" + spec + "'");
    truth = option.substr(6);
  }
  if (config.empty()) throw std::invalid_argument("sim: needs a config file: sim:CONFIG.yaml");
  SimConfig loaded = LoadSimConfig(config);
  if (truth.empty()) truth = loaded.truth_path;  // the config's own truth: field, else the default
  if (truth.empty()) truth = DefaultSimTruthPath(config);
  return std::make_unique<SimSource>(std::move(loaded), loop, truth);
}

}  // namespace ws
