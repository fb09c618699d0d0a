#include "source/dir_source.h"

#include <algorithm>
#include <filesystem>
#include <set>
#include <stdexcept>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace ws {
namespace {

namespace fs = std::filesystem;

bool IsImage(const fs::path& path) {
  static const std::set<std::string> kExtensions = {".jpg", ".jpeg", ".png", ".bmp", ".pgm",
                                                    ".ppm", ".pnm", ".tif", ".tiff"};
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
  return kExtensions.count(ext) > 0;
}

cv::Mat ReadImage(const std::string& path) {
  cv::Mat image = cv::imread(path, cv::IMREAD_UNCHANGED);
  if (image.empty()) return image;
  if (image.channels() == 4) cv::cvtColor(image, image, cv::COLOR_BGRA2BGR);
  if (image.depth() != CV_8U && image.depth() != CV_16U) return cv::Mat();
  return image;
}

}  // namespace

fs::directory_iterator OpenDir(const std::string& dir) {
  std::error_code error;
  fs::directory_iterator it(dir, error);
  if (error) throw std::runtime_error("cannot read image directory " + dir + ": " + error.message());
  return it;
}

void SortByLeft(std::vector<ImagePairPaths>* pairs) {
  std::sort(pairs->begin(), pairs->end(),
            [](const ImagePairPaths& a, const ImagePairPaths& b) { return a.left < b.left; });
}

std::vector<ImagePairPaths> FindImages(const std::string& dir) {
  std::vector<ImagePairPaths> images;
  for (const auto& entry : OpenDir(dir))
    if (entry.is_regular_file() && IsImage(entry.path())) images.push_back({entry.path().string(), ""});
  if (images.empty()) throw std::runtime_error("no images in " + dir);
  SortByLeft(&images);
  return images;
}

std::vector<ImagePairPaths> FindImagePairs(const std::string& dir) {
  std::vector<ImagePairPaths> pairs;
  for (const auto& entry : OpenDir(dir)) {
    const std::string name = entry.path().filename().string();
    const size_t at = name.find("left");
    if (!entry.is_regular_file() || !IsImage(entry.path()) || at == std::string::npos) continue;
    const fs::path right = entry.path().parent_path() / (name.substr(0, at) + "right" + name.substr(at + 4));
    if (fs::is_regular_file(right)) pairs.push_back({entry.path().string(), right.string()});
  }
  if (pairs.empty())
    throw std::runtime_error("no left/right image pairs in " + dir +
                             " (names must differ only in 'left' and 'right')");
  SortByLeft(&pairs);
  return pairs;
}

DirSource::DirSource(const std::string& dir, bool loop, bool mono)
    : dir_(dir), mono_(mono), pairs_(mono ? FindImages(dir) : FindImagePairs(dir)), loop_(loop) {}

std::optional<StereoPair> DirSource::Next() {
  if (next_ == pairs_.size()) {
    if (!loop_) return std::nullopt;
    if (consecutive_unreadable_ >= pairs_.size())
      throw std::runtime_error("no pair in the directory can be read as two images of one size");
    next_ = 0;
  }
  const ImagePairPaths& paths = pairs_[next_++];
  StereoPair pair;
  pair.left = ReadImage(paths.left);
  pair.label = fs::path(paths.left).filename().string();
  if (!mono_) {
    pair.right = ReadImage(paths.right);
    pair.label += " + " + fs::path(paths.right).filename().string();
  }
  const bool readable = mono_ ? !pair.left.empty()
                              : !pair.left.empty() && !pair.right.empty() &&
                                    pair.left.size() == pair.right.size() &&
                                    pair.left.type() == pair.right.type();
  if (!readable) {
    pair.label = "unreadable, or two images of different size or type: " + pair.label;
    pair.left = pair.right = cv::Mat();
    ++unreadable_;
    ++consecutive_unreadable_;
  } else {
    ++read_;
    consecutive_unreadable_ = 0;
  }
  return pair;
}

std::map<std::string, SourceCounts> DirSource::Counters() const {
  return {{"dir:" + dir_, {read_, 0, unreadable_}}};
}

}  // namespace ws
