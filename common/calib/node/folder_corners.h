// stereo-calibrate --images: a folder of images (any layout of
// source/image_folder.h) to the board corners of every pair, written as the
// STEREO_CORNERS log that stereo-capture + stereo-detect would have written,
// so that what follows is the offline --once solve of that log, and the log
// can be solved again with other options.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "detect/stereo_corner_finder.h"
#include "runtime/text_log.h"
#include "source/image_folder.h"

namespace ws::calib {

struct FolderCorners {
  ImageFolder folder;
  std::map<int64_t, std::string> names;  // frame id -> "left01.jpg + right01.jpg"
  int read = 0;                          // pairs (images, one camera) read
  int left_boards = 0, right_boards = 0;
  int unrefined = 0;  // corners found but dropped: their refinement failed (BoardCorners::unrefined)
  std::vector<std::string> unreadable, left_without_board, right_without_board;  // image names
};

// Reads every pair of `dir` (with `mono`, or a folder of no stereo layout:
// every image alone), finds the board on `workers` threads and writes each
// frame's corners to the LCM log `corners_log`, whole at the end, every
// write checked (atomic_file.h); says on `log` what it read, how many boards
// each camera shows and which images show none. Throws std::runtime_error
// with what to do when nothing can be read, when no image shows the board
// (naming a size that is found), when the images show a larger board than
// `finder`'s, of which it would find parts, or naming `corners_log` when it
// cannot be written. Throws Stopped (runtime/stop_request.h) when a stop is
// requested before every pair is read, its images in hand detected and no
// log written.
FolderCorners DetectFolder(const std::string& dir, bool mono, const StereoCornerFinder& finder, int workers,
                           const std::string& corners_log, TextLog& log);

}  // namespace ws::calib
