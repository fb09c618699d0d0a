#include "match/frame_image_writer.h"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include <opencv2/imgcodecs.hpp>

namespace ws {

std::string FrameImagePath(const std::string& dir, const std::string& name, int64_t frame_id) {
  char file[64];
  std::snprintf(file, sizeof file, "%s_%06lld.png", name.c_str(), static_cast<long long>(frame_id));
  return dir + "/" + file;
}

FrameImageWriter::FrameImageWriter(ImageSaveConfig config, std::string option)
    : config_(std::move(config)), option_(std::move(option)) {
  if (config_.save_every < 1)
    throw std::invalid_argument("--save-every: must be >= 1, got " + std::to_string(config_.save_every));
  if (config_.dir.empty()) return;
  std::error_code error;
  std::filesystem::create_directories(config_.dir, error);
  if (error)
    throw std::runtime_error(option_ + ": cannot create '" + config_.dir + "': " + error.message());
}

bool FrameImageWriter::Wants(int64_t frame_id) const {
  return !config_.dir.empty() && frame_id >= 0 && frame_id % config_.save_every == 0;
}

void FrameImageWriter::Write(int64_t frame_id, const std::vector<std::pair<std::string, cv::Mat>>& images) const {
  for (const auto& [name, image] : images) {
    const std::string path = FrameImagePath(config_.dir, name, frame_id);
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
