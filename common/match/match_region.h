// The part of a rectified pair stereo-match matches: the box of the common
// field (Rectification::common, where both rectified images hold image)
// grown by the matcher's reach (MatcherReach), so that every pixel of the
// box is matched with its whole disparity search and window, on the
// downscaled grid of the whole image. The empty borders about it are not
// remapped or matched: they could only give disparities the no-image mask
// removes. SGBM's paths start at the region's edges instead of the image's,
// so disparities near them can differ from a match of the whole image.
#pragma once

#include <opencv2/core.hpp>

#include "match/matcher.h"
#include "rectify/rectification.h"

namespace ws {

// The whole image when config.common_field_only is false or the images have
// no common field (then the mask leaves no disparity anyway).
cv::Rect MatchRegion(const Rectification& rect, const MatcherConfig& config);

// The region's columns left of the common field: they hold no image in one
// of the pair, so need no disparity of their own, and serve as the
// matcher's left margin (DisparityMatcher::Compute's context_columns).
int ContextColumns(const Rectification& rect, const cv::Rect& region);

}  // namespace ws
