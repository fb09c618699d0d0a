// The small image the page lists a calibration view with (STEREO_THUMBNAILS):
// stereo-detect sends one of every frame in which it found a board, just
// before the frame's corners, so that stereo-view need neither receive nor
// hold full frames to draw the list. A frame stereo-view dropped under
// load still gets its thumbnail: the detector saw the frame, and a
// thumbnail (a 128x96 grey image: 12 KB) is small enough not to be dropped
// with it.
#pragma once

#include "widestereo/stereo_corners_t.hpp"
#include "widestereo/stereo_frame_t.hpp"

namespace ws {

inline constexpr int kThumbnailWidth = 128;

// A frame of `frame`'s id and utime whose left image is the image a view of
// it is drawn on (the left one, unless only the right saw the board), scaled
// down to kThumbnailWidth across (a narrower image as it is: a thumbnail is
// never larger than its image), raw, and with no right image (as a
// one-camera rig's frame). Throws DecodeError for an image that does not decode.
widestereo::stereo_frame_t ThumbnailFrame(const widestereo::stereo_frame_t& frame,
                                          const widestereo::stereo_corners_t& corners);

}  // namespace ws
