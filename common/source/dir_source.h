// A folder of stereo pairs in any layout of image_folder.h (left*/right*
// names, left/ + right/, cam0/ + cam1/), in sorted order of the left name.
// An image without its partner is named in the first events.
//
// Every image's size is read from its header before anything is decoded
// (image_header.h). A pair comes back with empty images, its label naming
// the file and the reason (and is counted), when an image is no regular
// file (a folder, a device, a FIFO, a symlink loop), has no header with a
// size, claims more than `max_image_pixels`, or is not of the size most
// readable pairs share (the rig's, whatever the order), or when it then
// does not decode. 16-bit colour comes as 8-bit, alpha dropped. When the
// folder ends without one readable pair, Next() throws.
//
// With `loop`, the pairs read in the first lap are kept decoded while they
// fit in kLoopCacheBytes, and later laps serve them from memory (a looped
// folder stands in for cameras, which cost no image decoding; files changed
// after the first lap are not read again).
//
// With `mono` (a one-camera rig), every image of the folder in name order is
// the left image of a pair with no right image. Without it, a folder of
// images with no stereo layout is an error that suggests --mono.
#pragma once

#include <string>
#include <vector>

#include "lcm_io/image_codec.h"
#include "source/image_folder.h"
#include "source/stereo_source.h"

namespace ws {

class DirSource : public StereoSource {
 public:
  static constexpr size_t kLoopCacheBytes = size_t(256) << 20;

  DirSource(const std::string& dir, bool loop, bool mono = false,
            int64_t max_image_pixels = kDefaultMaxImagePixels);
  // The images of a folder already found (FindImageFolder); a one-camera
  // folder is a one-camera rig.
  DirSource(std::string dir, ImageFolder folder, bool loop, int64_t max_image_pixels = kDefaultMaxImagePixels);
  std::optional<StereoPair> Next() override;
  std::map<std::string, SourceCounts> Counters() const override;
  std::vector<std::string> TakeEvents() override;
  bool Mono() const override { return mono_; }

 private:
  std::string dir_;
  bool mono_;
  ImageFolder folder_;
  std::vector<std::string> events_;
  std::vector<std::string> refused_;  // per pair: why it is left out before decoding, "" if not
  bool loop_;
  size_t next_ = 0;
  std::vector<StereoPair> lap_;  // with loop_: the first lap's pairs, while they fit
  size_t lap_bytes_ = 0;
  int64_t read_ = 0;
  int64_t unreadable_ = 0;
};

}  // namespace ws
