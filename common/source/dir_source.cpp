#include "source/dir_source.h"

#include <stdexcept>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace ws {
namespace {

cv::Mat ReadImage(const std::string& path) {
  cv::Mat image = cv::imread(path, cv::IMREAD_UNCHANGED);
  if (image.empty()) return image;
  if (image.channels() == 4) cv::cvtColor(image, image, cv::COLOR_BGRA2BGR);
  if (image.depth() != CV_8U && image.depth() != CV_16U) return cv::Mat();
  return image;
}

ImageFolder StereoOrMonoFolder(const std::string& dir, bool mono) {
  ImageFolder folder = FindImageFolder(dir, mono);
  if (!mono && folder.layout == FolderLayout::kOneCamera)
    throw std::runtime_error("no stereo pairs in " + dir +
                             ": no left*/right* names, no left/ + right/ or cam0/ + cam1/ folders (" +
                             std::to_string(folder.pairs.size()) + " images; for a one-camera rig use --mono)");
  return folder;
}

}  // namespace

DirSource::DirSource(const std::string& dir, bool loop, bool mono)
    : DirSource(dir, StereoOrMonoFolder(dir, mono), loop) {}

DirSource::DirSource(std::string dir, ImageFolder folder, bool loop)
    : dir_(std::move(dir)), mono_(folder.layout == FolderLayout::kOneCamera), folder_(std::move(folder)), loop_(loop) {
  events_.push_back(dir_ + ": " + std::to_string(folder_.pairs.size()) + (mono_ ? " images, " : " pairs, ") +
                    LayoutName(folder_.layout));
  for (const std::string& alone : folder_.unpaired)
    events_.push_back("warning: " + ImageName(alone, dir_) + " has no partner image: left out");
}

std::vector<std::string> DirSource::TakeEvents() { return std::move(events_); }

std::optional<StereoPair> DirSource::Next() {
  if (next_ == folder_.pairs.size()) {
    if (read_ == 0)
      throw std::runtime_error("nothing in " + dir_ + " could be read as " +
                               (mono_ ? "an image" : "two images of one size and type"));
    if (!loop_) return std::nullopt;
    next_ = 0;
  }
  if (next_ < lap_.size()) {
    ++(lap_[next_].left.empty() ? unreadable_ : read_);
    return lap_[next_++];  // shares the pixels: the caller only reads them
  }
  const bool cache = loop_ && lap_.size() == next_;
  const ImagePairPaths& paths = folder_.pairs[next_++];
  StereoPair pair;
  pair.left = ReadImage(paths.left);
  pair.label = ImageName(paths.left, dir_);
  if (!mono_) {
    pair.right = ReadImage(paths.right);
    pair.label += " + " + ImageName(paths.right, dir_);
  }
  const bool readable = mono_ ? !pair.left.empty()
                              : !pair.left.empty() && !pair.right.empty() &&
                                    pair.left.size() == pair.right.size() &&
                                    pair.left.type() == pair.right.type();
  if (!readable) {
    pair.label = "unreadable, or two images of different size or type: " + pair.label;
    pair.left = pair.right = cv::Mat();
    ++unreadable_;
  } else {
    ++read_;
  }
  const size_t bytes = pair.left.total() * pair.left.elemSize() + pair.right.total() * pair.right.elemSize();
  if (cache && lap_bytes_ + bytes <= kLoopCacheBytes) {
    lap_.push_back(pair);
    lap_bytes_ += bytes;
  }
  return pair;
}

std::map<std::string, SourceCounts> DirSource::Counters() const {
  return {{"dir:" + dir_, {read_, 0, unreadable_}}};
}

}  // namespace ws
