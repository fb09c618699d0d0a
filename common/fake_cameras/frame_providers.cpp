#include "fake_cameras/frame_providers.h"

#include <cctype>
#include <filesystem>
#include <map>
#include <memory>
#include <utility>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "capture/camera_error.h"
#include "fake_cameras/sim_frames.h"

namespace ws {
namespace {

constexpr int kPatternSpeedPx = 4;      // per frame
constexpr int kPatternTravelPx = 1024;  // then it starts over
constexpr int kPatternDisparityPx = 32;
constexpr int kPatternDotPx = 4;  // side of one random dot
constexpr uint64_t kPatternSeed = 20240611;

const char* const kImageExtensions[] = {".png", ".jpg",  ".jpeg", ".bmp",
                                        ".tif", ".tiff", ".pgm",  ".ppm"};

cv::Mat ReadImage(const std::string& path) {
  cv::Mat image = cv::imread(path, cv::IMREAD_UNCHANGED);
  if (image.empty()) throw CameraError("cannot read image " + path);
  return image;
}

bool IsImage(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
  for (const char* known : kImageExtensions)
    if (extension == known) return true;
  return false;
}

}  // namespace

StereoFrameProvider MovingTestPattern(cv::Size size) {
  if (size.width <= 0 || size.height <= 0) throw CameraError("test pattern size must be positive");
  const cv::Size texture_size(size.width + kPatternTravelPx + kPatternDisparityPx, size.height);
  cv::Mat dots((texture_size.height + kPatternDotPx - 1) / kPatternDotPx,
               (texture_size.width + kPatternDotPx - 1) / kPatternDotPx, CV_8UC1);
  cv::RNG rng(kPatternSeed);
  rng.fill(dots, cv::RNG::UNIFORM, 0, 256);
  cv::Mat texture;
  cv::resize(dots, texture, cv::Size(), kPatternDotPx, kPatternDotPx, cv::INTER_NEAREST);
  return [texture, size](int64_t frame_index, bool left) {
    const int x =
        int((frame_index * kPatternSpeedPx) % kPatternTravelPx) + (left ? 0 : kPatternDisparityPx);
    return texture(cv::Rect(x, 0, size.width, size.height));
  };
}

StereoFrameProvider ImagePairFrames(const std::string& left_path, const std::string& right_path) {
  const cv::Mat left = ReadImage(left_path);
  const cv::Mat right = ReadImage(right_path);
  return [left, right](int64_t, bool is_left) { return is_left ? left : right; };
}

StereoFrameProvider ImageDirectoryFrames(const std::string& directory) {
  namespace fs = std::filesystem;
  std::error_code error;
  fs::directory_iterator entries(directory, error);
  if (error) throw CameraError("cannot list " + directory + ": " + error.message());
  std::map<std::string, std::pair<std::string, std::string>> by_rest;  // rest of name -> paths
  for (const fs::directory_entry& entry : entries) {
    if (!entry.is_regular_file() || !IsImage(entry.path())) continue;
    const std::string name = entry.path().filename().string();
    if (name.rfind("left", 0) == 0) by_rest[name.substr(4)].first = entry.path().string();
    if (name.rfind("right", 0) == 0) by_rest[name.substr(5)].second = entry.path().string();
  }
  std::vector<std::pair<std::string, std::string>> pairs;
  for (const auto& [rest, paths] : by_rest) {
    if (paths.first.empty() || paths.second.empty())
      throw CameraError(directory + ": " + (paths.first.empty() ? "right" : "left") + rest +
                        " has no " + (paths.first.empty() ? "left" : "right") + rest);
    pairs.push_back(paths);
  }
  if (pairs.empty()) throw CameraError(directory + ": no left*/right* image pairs");
  auto shared =
      std::make_shared<const std::vector<std::pair<std::string, std::string>>>(std::move(pairs));
  return [shared](int64_t frame_index, bool left) {
    const auto& pair = (*shared)[size_t(frame_index % int64_t(shared->size()))];
    return ReadImage(left ? pair.first : pair.second);
  };
}

StereoFrameProvider MakeFrameProvider(const std::string& spec, cv::Size pattern_size) {
  if (spec == "pattern") return MovingTestPattern(pattern_size);
  if (spec.rfind("dir:", 0) == 0) return ImageDirectoryFrames(spec.substr(4));
  if (spec.rfind("sim:", 0) == 0) return SimulatorFrames(spec.substr(4));
  if (spec.rfind("pair:", 0) == 0) {
    const std::string paths = spec.substr(5);
    const auto comma = paths.find(',');
    if (comma != std::string::npos)
      return ImagePairFrames(paths.substr(0, comma), paths.substr(comma + 1));
  }
  throw CameraError("frames '" + spec + "': expected pattern, pair:LEFT,RIGHT, dir:PATH or sim:CONFIG.yaml");
}

}  // namespace ws
