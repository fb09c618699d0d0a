// A directory of stereo pairs: files whose names differ only in "left" and
// "right" (left01.jpg/right01.jpg, left_03.png/right_03.png, ...), in sorted
// order of the left name. A pair that cannot be read as two images of one
// size and type comes back with empty images (and is counted).
//
// With `mono` (a one-camera rig), every image of the directory in name
// order is the left image of a pair with no right image.
#pragma once

#include <string>
#include <vector>

#include "source/stereo_source.h"

namespace ws {

struct ImagePairPaths {
  std::string left;
  std::string right;
};

// The pairs in `dir`, sorted. Throws std::runtime_error when the directory
// cannot be read or holds no pair.
std::vector<ImagePairPaths> FindImagePairs(const std::string& dir);
// Every image in `dir`, sorted, as pairs with no right image. Throws
// std::runtime_error when the directory cannot be read or holds no image.
std::vector<ImagePairPaths> FindImages(const std::string& dir);

class DirSource : public StereoSource {
 public:
  DirSource(const std::string& dir, bool loop, bool mono = false);
  std::optional<StereoPair> Next() override;
  std::map<std::string, SourceCounts> Counters() const override;
  bool Mono() const override { return mono_; }

 private:
  std::string dir_;
  bool mono_;
  std::vector<ImagePairPaths> pairs_;
  bool loop_;
  size_t next_ = 0;
  int64_t read_ = 0;
  int64_t unreadable_ = 0;
  size_t consecutive_unreadable_ = 0;
};

}  // namespace ws
