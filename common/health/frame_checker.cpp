#include "health/frame_checker.h"

#include <stdexcept>
#include <string>

#include <opencv2/imgproc.hpp>

namespace ws {
namespace {

// The grey 8-bit image the features are found in.
cv::Mat Gray8(const cv::Mat& image) {
  cv::Mat gray = image;
  if (image.channels() == 3) cv::cvtColor(image, gray, cv::COLOR_BGR2GRAY);
  if (image.channels() == 4) cv::cvtColor(image, gray, cv::COLOR_BGRA2GRAY);
  if (gray.depth() == CV_16U) gray.convertTo(gray, CV_8U, 1 / 257.0);
  if (gray.type() != CV_8UC1) throw std::invalid_argument("stereo-health needs 8- or 16-bit images");
  return gray;
}

std::string SizeText(cv::Size size) { return std::to_string(size.width) + "x" + std::to_string(size.height); }

}  // namespace

FrameChecker::FrameChecker(const Rig& rig, const RectifyOptions& rectify, const FeatureOptions& features)
    : rect_(BuildRectification(rig, rectify)),
      features_(features),
      filled_left_(FilledRegion(rect_, true, features.border_px)),
      filled_right_(FilledRegion(rect_, false, features.border_px)) {}

FrameCheck FrameChecker::Check(const cv::Mat& left, const cv::Mat& right, const std::string& source) const {
  if (left.size() != rect_.input_size || right.size() != rect_.input_size)
    throw std::invalid_argument("the images are " + SizeText(left.size()) + " but " + source + " is for " +
                                SizeText(rect_.input_size));
  cv::Mat left_rect, right_rect;
  RectifyPair(rect_, Gray8(left), Gray8(right), &left_rect, &right_rect);
  FrameCheck check;
  check.matches = MatchRectifiedPair(left_rect, right_rect, filled_left_, filled_right_, rect_, features_);
  const RectifiedMatches& m = check.matches;
  for (size_t i = 0; i < m.left.size(); ++i) {
    check.dy.push_back({m.left[i], m.right[i].y - m.left[i].y});
    check.rays.push_back(
        {RectifiedPixelRay(rect_, true, m.left[i]), RectifiedPixelRay(rect_, false, m.right[i]), m.left[i]});
  }
  return check;
}

}  // namespace ws
