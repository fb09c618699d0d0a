#include "fake_cameras/sim_frames.h"

#include <memory>
#include <utility>
#include <vector>

#include "source/sim_source.h"

namespace ws {

StereoFrameProvider SimulatorFrames(const std::string& spec) {
  const std::unique_ptr<SimSource> source = MakeSimSource(spec, false);
  const Simulator& simulator = source->simulator();
  auto frames = std::make_shared<std::vector<std::pair<cv::Mat, cv::Mat>>>(simulator.frame_count());
  cv::parallel_for_(cv::Range(0, simulator.frame_count()), [&](const cv::Range& range) {
    for (int k = range.start; k < range.end; ++k) (*frames)[size_t(k)] = simulator.Render(k);
  });
  return [frames](int64_t frame_index, bool left) {
    const auto& pair = (*frames)[size_t(frame_index % int64_t(frames->size()))];
    return left ? pair.first : pair.second;
  };
}

}  // namespace ws
