#include "source/dir_source.h"

#include <algorithm>
#include <map>
#include <stdexcept>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "source/image_header.h"

namespace ws {
namespace {

// The image decoded, 16-bit colour as 8-bit and alpha dropped (16-bit grey
// stays: Mono16); empty with `*why` when it does not decode.
cv::Mat ReadImage(const std::string& path, std::string* why) {
  cv::Mat image;
  try {
    image = cv::imread(path, cv::IMREAD_UNCHANGED);
  } catch (const cv::Exception& e) {
    *why = "does not decode: " + e.err;
    return cv::Mat();
  }
  if (image.empty()) {
    *why = "does not decode";
    return image;
  }
  if (image.channels() == 4) cv::cvtColor(image, image, cv::COLOR_BGRA2BGR);
  if (image.channels() == 3 && image.depth() == CV_16U) image.convertTo(image, CV_8U, 1.0 / 257);
  if (image.depth() != CV_8U && image.depth() != CV_16U) {
    *why = "neither 8 nor 16 bits a channel";
    return cv::Mat();
  }
  return image;
}

// Why each pair of `folder` is left out before any decoding ("" for none):
// an image whose header gives no size or more than `max_pixels`, the two of
// a pair of different sizes, or a pair not of the size most pairs share.
std::vector<std::string> RefusedBeforeDecoding(const ImageFolder& folder, const std::string& dir, bool mono,
                                               int64_t max_pixels) {
  std::vector<std::string> refused(folder.pairs.size());
  std::vector<cv::Size> sizes(folder.pairs.size());
  std::map<std::pair<int, int>, int> shared;  // size -> pairs of it
  for (size_t i = 0; i < folder.pairs.size(); ++i) {
    const ImagePairPaths& p = folder.pairs[i];
    for (const std::string* path : {&p.left, &p.right}) {
      if (mono && path == &p.right) break;
      std::string why;
      const auto size = DecodableImageSize(*path, max_pixels, &why);
      if (!size)
        refused[i] = ImageName(*path, dir) + ": " + why;
      else if (path == &p.right && *size != sizes[i])
        refused[i] = ImageName(p.left, dir) + " + " + ImageName(p.right, dir) + ": images of different sizes";
      if (!refused[i].empty()) break;
      sizes[i] = *size;
    }
    if (refused[i].empty()) ++shared[{sizes[i].width, sizes[i].height}];
  }
  if (shared.empty()) return refused;
  const auto rig = std::max_element(shared.begin(), shared.end(),
                                    [](const auto& a, const auto& b) { return a.second < b.second; })->first;
  for (size_t i = 0; i < folder.pairs.size(); ++i)
    if (refused[i].empty() && (sizes[i].width != rig.first || sizes[i].height != rig.second))
      refused[i] = ImageName(folder.pairs[i].left, dir) + ": " + std::to_string(sizes[i].width) + "x" +
                   std::to_string(sizes[i].height) + ", where " + std::to_string(shared[rig]) + " of the folder's " +
                   (mono ? "images" : "pairs") + " are " + std::to_string(rig.first) + "x" + std::to_string(rig.second);
  return refused;
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

DirSource::DirSource(const std::string& dir, bool loop, bool mono, int64_t max_image_pixels)
    : DirSource(dir, StereoOrMonoFolder(dir, mono), loop, max_image_pixels) {}

DirSource::DirSource(std::string dir, ImageFolder folder, bool loop, int64_t max_image_pixels)
    : dir_(std::move(dir)),
      mono_(folder.layout == FolderLayout::kOneCamera),
      folder_(std::move(folder)),
      refused_(RefusedBeforeDecoding(folder_, dir_, mono_, max_image_pixels)),
      loop_(loop) {
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
  std::string why = refused_[next_ - 1];
  if (why.empty()) {
    pair.left = ReadImage(paths.left, &why);
    if (!mono_ && why.empty()) pair.right = ReadImage(paths.right, &why);
    if (why.empty() && !mono_ && (pair.left.size() != pair.right.size() || pair.left.type() != pair.right.type()))
      why = "two images of different size or type";
    if (!why.empty()) why = ImageName(paths.left, dir_) + (mono_ ? "" : " + " + ImageName(paths.right, dir_)) + ": " + why;
  }
  pair.label = ImageName(paths.left, dir_) + (mono_ ? "" : " + " + ImageName(paths.right, dir_));
  if (!why.empty()) {
    pair.label = why;
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
