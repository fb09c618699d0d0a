#include "match/rectified_pair_writer.h"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include <opencv2/imgcodecs.hpp>

namespace ws {

std::string RectifiedImagePath(const std::string& dir, const std::string& side, int64_t frame_id) {
  char name[64];
  std::snprintf(name, sizeof name, "%s_%06lld.png", side.c_str(), static_cast<long long>(frame_id));
  return dir + "/" + name;
}

RectifiedPairWriter::RectifiedPairWriter(RectifiedSaveConfig config) : config_(std::move(config)) {
  if (config_.save_every < 1)
    throw std::invalid_argument("--save-every: must be >= 1, got " + std::to_string(config_.save_every));
  if (config_.dir.empty()) return;
  std::error_code error;
  std::filesystem::create_directories(config_.dir, error);
  if (error)
    throw std::runtime_error("--save-rectified: cannot create '" + config_.dir + "': " + error.message());
}

bool RectifiedPairWriter::Wants(int64_t frame_id) const {
  return !config_.dir.empty() && frame_id >= 0 && frame_id % config_.save_every == 0;
}

void RectifiedPairWriter::Write(int64_t frame_id, const cv::Mat& left, const cv::Mat& right) const {
  for (const auto& [side, image] : {std::pair<const char*, const cv::Mat&>{"left", left}, {"right", right}}) {
    const std::string path = RectifiedImagePath(config_.dir, side, frame_id);
    bool written = false;
    try {
      written = cv::imwrite(path, image);
    } catch (const cv::Exception& e) {
      throw std::runtime_error("cannot write " + path + ": " + e.what());
    }
    if (!written) throw std::runtime_error("cannot write " + path);
  }
}

}  // namespace ws
