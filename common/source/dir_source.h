// A folder of stereo pairs in any layout of image_folder.h (left*/right*
// names, left/ + right/, cam0/ + cam1/), in sorted order of the left name.
// An image without its partner is named in the first events. A pair that
// cannot be read as two images of one size and type comes back with empty
// images (and is counted); when the folder ends without one readable pair,
// Next() throws.
//
// With `mono` (a one-camera rig), every image of the folder in name order is
// the left image of a pair with no right image. Without it, a folder of
// images with no stereo layout is an error that suggests --mono.
#pragma once

#include <string>
#include <vector>

#include "source/image_folder.h"
#include "source/stereo_source.h"

namespace ws {

class DirSource : public StereoSource {
 public:
  DirSource(const std::string& dir, bool loop, bool mono = false);
  // The images of a folder already found (FindImageFolder); a one-camera
  // folder is a one-camera rig.
  DirSource(std::string dir, ImageFolder folder, bool loop);
  std::optional<StereoPair> Next() override;
  std::map<std::string, SourceCounts> Counters() const override;
  std::vector<std::string> TakeEvents() override;
  bool Mono() const override { return mono_; }

 private:
  std::string dir_;
  bool mono_;
  ImageFolder folder_;
  std::vector<std::string> events_;
  bool loop_;
  size_t next_ = 0;
  int64_t read_ = 0;
  int64_t unreadable_ = 0;
};

}  // namespace ws
