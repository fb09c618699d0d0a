#include "detect/corner_refinement.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "detect/saddle_point.h"

namespace ws {
namespace {

constexpr double kLargestScaleOfSpacing = 0.15;
constexpr double kLargestScalePx = 16;
constexpr double kAgreementErrors = 3;  // Lepski's threshold, in standard errors
constexpr double kPoorFit = 0.75;       // share of the window's variance explained

// Scales 1, sqrt 2, 2, ... 16 px: the fit's windows, made once.
const std::vector<SaddleWindow>& Ladder() {
  static const std::vector<SaddleWindow> ladder = [] {
    std::vector<SaddleWindow> windows;
    for (double sigma = 1; sigma <= kLargestScalePx * (1 + 1e-9); sigma *= std::sqrt(2.0))
      windows.emplace_back(sigma);
    return windows;
  }();
  return ladder;
}

struct Estimate {
  cv::Point2f point;
  double error;  // standard error, pixels
};

}  // namespace

void CornerSubPix(const cv::Mat& gray, std::vector<cv::Point2f>& points, const std::vector<double>& spacing) {
  CV_Assert(spacing.size() == points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    const int half = std::clamp(static_cast<int>(0.4 * spacing[i]), 2, 11);
    std::vector<cv::Point2f> one{points[i]};
    cv::cornerSubPix(gray, one, cv::Size(half, half), cv::Size(-1, -1),
                     cv::TermCriteria(cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 40, 0.001));
    points[i] = one.front();
  }
}

double ImageNoise(const cv::Mat& gray, cv::Rect region) {
  region &= cv::Rect(0, 0, gray.cols, gray.rows);
  constexpr double kRounding = 1.0 / 12;  // variance of rounding to whole grey levels
  if (region.width < 3 || region.height < 3) return std::sqrt(kRounding);
  // The Laplacian difference [1 -2 1; -2 4 -2; 1 -2 1] cancels anything
  // locally planar; on white noise its response has 6 times its deviation.
  const cv::Mat kernel = (cv::Mat_<float>(3, 3) << 1, -2, 1, -2, 4, -2, 1, -2, 1);
  cv::Mat response;
  cv::filter2D(gray(region), response, CV_32F, kernel, cv::Point(-1, -1), 0, cv::BORDER_REPLICATE);
  std::vector<float> magnitudes;
  magnitudes.reserve(response.total());
  for (int y = 1; y + 1 < response.rows; ++y)
    for (int x = 1; x + 1 < response.cols; ++x) magnitudes.push_back(std::abs(response.at<float>(y, x)));
  auto middle = magnitudes.begin() + magnitudes.size() / 2;
  std::nth_element(magnitudes.begin(), middle, magnitudes.end());
  const double sigma = 1.4826 * *middle / 6;  // the median absolute deviation as a standard deviation
  return std::sqrt(sigma * sigma + kRounding);
}

int RefineCorners(const cv::Mat& gray, std::vector<cv::Point2f>& points, const std::vector<double>& spacing,
                  const std::vector<cv::Point2f>& fallback) {
  CV_Assert(spacing.size() == points.size() && fallback.size() == points.size());
  if (points.empty()) return 0;
  // The noise of the board's region: its corners and the squares around them.
  const int reach = static_cast<int>(std::ceil(*std::max_element(spacing.begin(), spacing.end())));
  cv::Rect region = cv::boundingRect(points);
  region = cv::Rect(region.x - reach, region.y - reach, region.width + 2 * reach, region.height + 2 * reach);
  const double noise = ImageNoise(gray, region);
  const std::vector<SaddleWindow>& ladder = Ladder();
  int fell_back = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    const double largest = std::max(ladder.front().sigma(), kLargestScaleOfSpacing * spacing[i]);
    std::vector<Estimate> accepted;
    for (const SaddleWindow& window : ladder) {
      if (window.sigma() > largest * (1 + 1e-9)) break;
      const auto fit = window.Fit(gray, points[i]);
      const bool good = fit && fit->explained >= kPoorFit;
      if (!good) {
        if (accepted.empty()) continue;  // too noisy yet: try a larger window
        break;
      }
      const Estimate estimate{fit->point, noise * fit->error_per_noise};
      const bool agrees = std::all_of(accepted.begin(), accepted.end(), [&](const Estimate& smaller) {
        return cv::norm(estimate.point - smaller.point) <= kAgreementErrors * smaller.error;
      });
      if (!agrees) break;
      accepted.push_back(estimate);
    }
    if (accepted.empty()) ++fell_back;
    points[i] = accepted.empty() ? fallback[i] : accepted.back().point;
  }
  return fell_back;
}

bool Unrefined(cv::Point2f point) { return point.x == std::floor(point.x) && point.y == std::floor(point.y); }

int DropUnrefined(std::vector<int>& ids, std::vector<cv::Point2f>& points) {
  CV_Assert(ids.size() == points.size());
  size_t kept = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    if (Unrefined(points[i])) continue;
    ids[kept] = ids[i];
    points[kept++] = points[i];
  }
  const int dropped = int(points.size() - kept);
  ids.resize(kept);
  points.resize(kept);
  return dropped;
}

}  // namespace ws
