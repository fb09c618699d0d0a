// The health verdict of the newest checked frames, with hysteresis.
//
// Each checked frame is usable when it has at least min_matches matches
// spread over at least min_regions regions; its own median |dy| then says
// ok (<= max_dy) or misaligned. The verdict changes to ok or misaligned only
// when the newest `confirm` usable frames of the window all say so; while
// they disagree it stays what it was, so one bad frame does not flip it. With
// fewer than `confirm` usable frames among the last `window` it is unknown:
// a textureless or dark scene never gives ok or misaligned from a handful of
// matches.
#pragma once

#include <deque>
#include <string>
#include <vector>

#include "health/dy_figures.h"

namespace ws {

struct VerdictOptions {
  double max_dy = 0.3;   // px, on a frame's median |dy|
  int window = 5;        // checked frames
  int confirm = 3;       // agreeing usable frames that set the verdict
  int min_matches = 25;  // per frame
  int min_regions = 1;   // regions holding at least one match, per frame
};

class VerdictWindow {
 public:
  explicit VerdictWindow(VerdictOptions options) : options_(options) {}

  // Adds a checked frame's matches; returns the verdict after it.
  const std::string& Add(std::vector<DyMatch> matches, const DyGrid& grid, cv::Size size);
  void Clear();

  const std::string& verdict() const { return verdict_; }
  // Every match of the window's usable frames, and how many frames they are.
  std::vector<DyMatch> Matches() const;
  int usable_frames() const;
  bool newest_usable() const { return !frames_.empty() && frames_.back().usable; }
  const VerdictOptions& options() const { return options_; }

 private:
  struct Frame {
    bool usable = false;
    bool ok = false;
    std::vector<DyMatch> matches;
  };
  VerdictOptions options_;
  std::deque<Frame> frames_;
  std::string verdict_ = "unknown";
};

}  // namespace ws
