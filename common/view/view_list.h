// The calibration's views as the page lists them (topic "views"): every view
// stereo-calibrate holds (CALIBRATION_VIEWS), named by its frame id, with its
// corner counts, the board's outline in each image, its RMS in the last
// solve, and a thumbnail of its left image (of its right one when the left
// did not see the board).
//
// Thumbnails: stereo-detect sends one (kThumbnailWidth pixels across,
// detect/thumbnail_frame.h) of each frame in which it found a board, before
// stereo-calibrate says whether it took a view from it; each is kept as a
// JPEG (Found), and the newest kCandidatesKept wait in memory for a
// CALIBRATION_VIEWS that lists them. A listed one goes to the BlobStore
// (the page fetches it) and stays while its view does, kThumbnailsKept at
// most (stereo-calibrate keeps 300 views unless --max-views says more):
// memory is bounded however long the session, and the bus carries nothing
// more than it did.
//
// Each update is the whole list and its change from the list before
// (EventHub sends a browser that holds the list before only the change):
//   whole:  {"solve_utime", "width": [l, r], "height": [l, r], "views": [newest first]}
//   change: {"solve_utime", "width", "height", "put": [views new or changed, oldest first],
//            "gone": [[frame_id, utime], ...]}
// A view is {"frame_id", "utime", "left_corners", "right_corners",
// "left_outline", "right_outline", "left_rms", "right_rms", "thumbnail"}.
// Not thread-safe: the input thread's.
#pragma once

#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "detect/thumbnail_frame.h"
#include "view/blob_store.h"
#include "widestereo/calibration_views_t.hpp"
#include "widestereo/stereo_frame_t.hpp"

namespace ws::view {

inline constexpr size_t kCandidatesKept = 64;
inline constexpr size_t kThumbnailsKept = 512;

class ViewList {
 public:
  struct Update {
    std::string whole, change;
  };

  explicit ViewList(BlobStore& blobs) : blobs_(blobs) {}

  // A STEREO_THUMBNAILS frame: its left image is the thumbnail of the frame
  // of that id and utime. Throws DecodeError for one that cannot be decoded
  // (nothing is kept).
  void Found(const widestereo::stereo_frame_t& thumbnail);

  // The update for `views`, or nothing when it says what the last one said
  // (the list changes when views come, go or are solved).
  std::optional<Update> Event(const widestereo::calibration_views_t& views);

 private:
  using Key = std::pair<int64_t, int64_t>;  // frame id, utime
  // The blob path of a listed view's thumbnail: kept, or made now of a
  // candidate; "" when there is none.
  std::string Thumbnail(const Key& key);

  BlobStore& blobs_;
  std::map<Key, std::shared_ptr<const Blob>> candidates_;  // thumbnails of frames not listed yet
  std::deque<Key> candidate_order_;                         // oldest first
  std::map<Key, std::string> thumbnails_;                   // the blob path of each listed view's thumbnail
  std::deque<std::pair<Key, std::string>> made_;  // in the order stored: the BlobStore forgets the oldest likewise
  std::string last_header_;
  std::map<Key, std::string> last_views_;  // each view of the last list, as sent
};

}  // namespace ws::view
