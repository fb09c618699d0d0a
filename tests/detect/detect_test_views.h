// Rendered board views shared by the detector tests.
#pragma once

#include <string>
#include <vector>

#include "detect/corner_detector.h"
#include "detect/synthetic_view.h"

namespace ws::test {

inline const std::string kOpenCvData = "/usr/share/doc/opencv-doc/examples/data";
// OpenCV's stereo calibration set there: left01/right01 ... left14/right14, no 10.
inline const std::vector<int> kOpenCvDocPairs = {1, 2, 3, 4, 5, 6, 7, 8, 9, 11, 12, 13, 14};
// "left01.jpg" for ("left", 1).
inline std::string OpenCvDocName(const std::string& side, int index) {
  return side + (index < 10 ? "0" : "") + std::to_string(index) + ".jpg";
}

// `count` views of `board` spread over roll, tilt, size and position, at `size`.
std::vector<SyntheticView> SpreadOfViews(const BoardSpec& board, cv::Size size, int count);

struct CornerErrors {
  double rms_px = 0;   // over the corners found
  int corners = 0;
  int views_found = 0;
};

// How far `detector`'s corners are from the truth, matched by id.
CornerErrors MeasureErrors(const CornerDetector& detector, const std::vector<SyntheticView>& views);

}  // namespace ws::test
