#include "source/aravis_source.h"

#include <chrono>

namespace ws {

AravisSource::AravisSource(const std::string& ids, const std::string& rig_config)
    : AravisSource(ParseAravisCameraIds(ids), LoadArvCameraSettings(rig_config)) {}

AravisSource::AravisSource(const std::pair<std::string, std::string>& ids, const ArvCameraSettings& settings)
    : left_name_("aravis:" + ids.first),
      right_name_("aravis:" + ids.second),
      pair_(ids.first, ids.second, settings) {}

std::optional<StereoPair> AravisSource::Next() {
  StereoPair pair;
  std::optional<StereoFrame> frames = pair_.Next(std::chrono::seconds(1));
  if (!frames) {
    pair.nothing_due = true;
    pair.label = pair_.connected() ? "no pair from the cameras for 1 s" : "waiting for the cameras";
    return pair;
  }
  pair.left = std::move(frames->left.image);
  pair.right = std::move(frames->right.image);
  pair.utime = frames->left.host_timestamp_ns / 1000;
  pair.label = "camera frames " + std::to_string(frames->left.frame_id) + ", " +
               std::to_string(frames->right.frame_id);
  return pair;
}

std::map<std::string, SourceCounts> AravisSource::Counters() const {
  const StereoPairCounters c = pair_.counters();
  const auto counts = [](const CameraCounters& camera, uint64_t unpaired) {
    return SourceCounts{int64_t(camera.completed), int64_t(camera.lost + unpaired), int64_t(camera.incomplete)};
  };
  return {{left_name_, counts(c.left, c.unpaired_left)}, {right_name_, counts(c.right, c.unpaired_right)}};
}

}  // namespace ws
