// The calibration's views as the page lists them (topic "views"): every view
// stereo-calibrate holds (CALIBRATION_VIEWS), named by its frame id, with its
// corner counts, the board's outline in each image, its RMS in the last
// solve, and a thumbnail of its left image (of its right one when the left
// did not see the board) when stereo-view still had that frame (one of the
// last frames it showed). Thumbnails are small
// (kThumbnailWidth pixels across) and few (the newest kThumbnailsKept, in
// the BlobStore): a session of hundreds of views costs the page's server
// at most kThumbnailsKept small JPEGs. Not thread-safe: the input thread's.
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "view/blob_store.h"
#include "widestereo/calibration_views_t.hpp"

namespace ws::view {

inline constexpr int kThumbnailWidth = 128;
inline constexpr size_t kThumbnailsKept = 64;

class ViewList {
 public:
  // An image ("left" or "right") of a frame the page was shown (its JPEG blob), or null.
  using FrameImage =
      std::function<std::shared_ptr<const Blob>(int64_t frame_id, int64_t utime, const std::string& side)>;

  ViewList(BlobStore& blobs, FrameImage frame_image);

  // The "views" event for `views`, or nothing when it says what the last
  // one said (the list changes when views come, go or are solved).
  std::optional<std::string> Event(const widestereo::calibration_views_t& views);

 private:
  using Key = std::pair<int64_t, int64_t>;  // frame id, utime
  // The thumbnail's blob path of a view, made now if its frame is at hand; "" when not.
  std::string Thumbnail(const Key& key, const std::string& side);

  BlobStore& blobs_;
  FrameImage frame_image_;
  std::map<Key, std::string> thumbnails_;  // the blob path of each view's thumbnail
  std::deque<std::pair<Key, std::string>> made_;  // in the order made: the BlobStore forgets the oldest likewise
  std::string last_;
};

}  // namespace ws::view
