// stereo-capture's --source aravis:LEFT_ID,RIGHT_ID: the pairs of an
// AravisStereoPair as a StereoSource.
//
// Counters, one input per camera ("aravis:ID"): received = complete frames,
// dropped = frames lost on the way plus frames that never found a partner,
// rejected = incomplete buffers (packets missing).
#pragma once

#include <string>

#include "capture/aravis_stereo_pair.h"
#include "source/stereo_source.h"

namespace ws {

class AravisSource : public StereoSource {
 public:
  // `ids` is the text after "aravis:"; `rig_config` a config/rig/*.yaml file.
  // Throws std::invalid_argument (ids) or RigConfigError (settings).
  AravisSource(const std::string& ids, const std::string& rig_config);

  // A pair, or (after a second without one) a pair with nothing_due set.
  std::optional<StereoPair> Next() override;
  std::map<std::string, SourceCounts> Counters() const override;
  std::vector<std::string> TakeEvents() override { return pair_.TakeEvents(); }
  bool Paced() const override { return true; }

 private:
  AravisSource(const std::pair<std::string, std::string>& ids, const ArvCameraSettings& settings);

  std::string left_name_, right_name_;
  AravisStereoPair pair_;
};

}  // namespace ws
