// Which of the page's two views some browser shows now. Each event stream
// says which one its page shows (/events?view=calibration or view=depth;
// none: both), and stereo-view makes a view's images, rectified pairs,
// disparities and clouds only while some stream watches it: with no page
// open, or a page on the other tab, those frames are skipped undecoded and
// cost the rig only their reception. Thread-safe.
#pragma once

#include <array>
#include <atomic>
#include <string>

namespace ws::view {

enum class PageView { kCalibration, kDepth };

class Audience {
 public:
  // What a stream shows, from its `view` parameter: "calibration", "depth",
  // or "" (both). Throws std::invalid_argument naming the two for another.
  struct Views {
    bool calibration = true, depth = true;
  };
  static Views Parse(const std::string& view);

  void Join(Views views);
  void Leave(Views views);
  bool Watching(PageView view) const;
  // Whether some stream shows any of `views`.
  bool Watching(Views views) const;

 private:
  std::array<std::atomic<int>, 2> streams_{};  // by PageView: the streams watching it
};

}  // namespace ws::view
