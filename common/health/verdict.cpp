#include "health/verdict.h"

namespace ws {

const std::string& VerdictWindow::Add(std::vector<DyMatch> matches, const DyGrid& grid, cv::Size size) {
  const DyFigures figures = ComputeDyFigures(matches, size, grid);
  Frame frame;
  frame.usable = figures.matches >= options_.min_matches && figures.regions_with(1) >= options_.min_regions;
  frame.ok = figures.median_abs <= options_.max_dy;
  if (frame.usable) frame.matches = std::move(matches);
  frames_.push_back(std::move(frame));
  while (int(frames_.size()) > options_.window) frames_.pop_front();

  int usable = 0, ok = 0;
  for (auto it = frames_.rbegin(); it != frames_.rend() && usable < options_.confirm; ++it)
    if (it->usable) {
      ++usable;
      ok += it->ok;
    }
  if (usable < options_.confirm)
    verdict_ = "unknown";
  else if (ok == usable)
    verdict_ = "ok";
  else if (ok == 0)
    verdict_ = "misaligned";
  // else: the newest usable frames disagree; the verdict stays.
  return verdict_;
}

void VerdictWindow::Clear() {
  frames_.clear();
  verdict_ = "unknown";
}

std::vector<DyMatch> VerdictWindow::Matches() const {
  std::vector<DyMatch> all;
  for (const Frame& frame : frames_) all.insert(all.end(), frame.matches.begin(), frame.matches.end());
  return all;
}

int VerdictWindow::usable_frames() const {
  int n = 0;
  for (const Frame& frame : frames_) n += frame.usable;
  return n;
}

}  // namespace ws
