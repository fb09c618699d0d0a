#include "health/rectified_matches.h"

#include <algorithm>
#include <cmath>

#include <opencv2/features2d.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/video/tracking.hpp>

namespace ws {
namespace {

constexpr int kPatch = 31;              // ORB's patch, pixels
constexpr float kMaxTrackShift = 2.0f;  // Lucas-Kanade's point from the matched corner, px
constexpr double kNarrowRows = 3;       // px: the narrow band of rows

struct Described {
  std::vector<cv::KeyPoint> keys;
  cv::Mat descriptors;
};

// Corners with upright ORB descriptors (ORB drops those too near the image
// border, so keypoints may be fewer than corners).
Described Describe(const cv::Mat& image, const std::vector<cv::Point2f>& corners) {
  Described d;
  for (const cv::Point2f& corner : corners) d.keys.emplace_back(corner, float(kPatch), 0.f);
  cv::ORB::create(int(corners.size()) + 1, 1.2f, 1, kPatch, 0, 2, cv::ORB::HARRIS_SCORE, kPatch)
      ->compute(image, d.keys, d.descriptors);
  return d;
}

constexpr int kModelTerms = 6;
constexpr int kRansacIterations = 300;

// The model's terms at a left rectified pixel: 1, x, y, x^2, x y, y^2.
void DyTerms(const Rectification& rect, const cv::Point2f& p, double* row) {
  const double x = (p.x - rect.cx) / rect.f, y = (p.y - rect.cy) / rect.f;
  const double terms[kModelTerms] = {1, x, y, x * x, x * y, y * y};
  std::copy(terms, terms + kModelTerms, row);
}

// Least squares over the rows of A selected by `use`.
cv::Mat FitDy(const cv::Mat& A, const cv::Mat& dy, const std::vector<int>& use) {
  cv::Mat a(int(use.size()), kModelTerms, CV_64F), b(int(use.size()), 1, CV_64F), coeffs;
  for (size_t i = 0; i < use.size(); ++i) {
    A.row(use[i]).copyTo(a.row(int(i)));
    b.at<double>(int(i)) = dy.at<double>(use[i]);
  }
  cv::solve(a, b, coeffs, cv::DECOMP_SVD);
  return coeffs;
}

std::vector<int> Inliers(const cv::Mat& A, const cv::Mat& dy, const cv::Mat& coeffs, double threshold) {
  const cv::Mat residual = cv::abs(A * coeffs - dy);
  std::vector<int> in;
  for (int i = 0; i < residual.rows; ++i)
    if (residual.at<double>(i) <= threshold) in.push_back(i);
  return in;
}

double DyModelAt(const Rectification& rect, const cv::Mat& coeffs, const cv::Point2f& p) {
  double terms[kModelTerms];
  DyTerms(rect, p, terms);
  return cv::Mat(1, kModelTerms, CV_64F, terms).dot(coeffs.t());
}

// RANSAC over the smooth dy model (header, step 4): 1 marks an inlier;
// `coeffs` is the model fitted to the inliers (empty without enough).
std::vector<uint8_t> DyModelInliers(const std::vector<cv::Point2f>& l, const std::vector<cv::Point2f>& r,
                                    const Rectification& rect, double threshold, cv::Mat* coeffs) {
  const int n = int(l.size());
  cv::Mat A(n, kModelTerms, CV_64F), dy(n, 1, CV_64F);
  for (int i = 0; i < n; ++i) {
    DyTerms(rect, l[size_t(i)], A.ptr<double>(i));
    dy.at<double>(i) = r[size_t(i)].y - l[size_t(i)].y;
  }
  cv::RNG rng(17);
  std::vector<int> best;
  for (int it = 0; it < kRansacIterations && n > kModelTerms; ++it) {
    std::vector<int> sample;
    while (int(sample.size()) < kModelTerms) {
      const int k = rng.uniform(0, n);
      if (std::find(sample.begin(), sample.end(), k) == sample.end()) sample.push_back(k);
    }
    std::vector<int> in = Inliers(A, dy, FitDy(A, dy, sample), threshold);
    if (in.size() > best.size()) best = std::move(in);
  }
  coeffs->release();
  if (int(best.size()) > kModelTerms) {
    best = Inliers(A, dy, FitDy(A, dy, best), threshold);
    if (int(best.size()) > kModelTerms) *coeffs = FitDy(A, dy, best);
  }
  std::vector<uint8_t> mask(size_t(n), 0);
  for (int i : best) mask[size_t(i)] = 1;
  return mask;
}

struct Pass {
  int candidates = 0, refined = 0;
  std::vector<cv::Point2f> left, right;
  cv::Mat model;  // the dy field of the inliers
};

// Steps 2-4 with candidates whose dy is within `rows` of expected_dy(left pixel).
template <class ExpectedDy>
Pass MatchPass(const cv::Mat& left, const cv::Mat& right, const Described& l, const Described& r,
               const Rectification& rect, const FeatureOptions& o, ExpectedDy expected_dy, double rows) {
  Pass pass;
  cv::Mat allowed(int(l.keys.size()), int(r.keys.size()), CV_8UC1);
  for (int i = 0; i < allowed.rows; ++i) {
    uint8_t* row = allowed.ptr<uint8_t>(i);
    const cv::Point2f& p = l.keys[size_t(i)].pt;
    const double dy0 = expected_dy(p);  // a field beyond the band is no field: no candidates
    for (int j = 0; j < allowed.cols; ++j) {
      const cv::Point2f& q = r.keys[size_t(j)].pt;
      const float dx = p.x - q.x;
      row[j] = std::abs(dy0) <= o.search_rows && std::abs(q.y - p.y - dy0) <= rows && dx >= -2 &&
               dx <= o.max_disparity;
    }
  }
  std::vector<std::vector<cv::DMatch>> knn;
  cv::BFMatcher(cv::NORM_HAMMING).knnMatch(l.descriptors, r.descriptors, knn, 2, allowed);
  std::vector<cv::Point2f> from, to;
  for (const auto& best : knn) {
    if (best.empty() || (best.size() == 2 && !(best[0].distance < o.ratio * best[1].distance))) continue;
    from.push_back(l.keys[size_t(best[0].queryIdx)].pt);
    to.push_back(r.keys[size_t(best[0].trainIdx)].pt);
  }
  pass.candidates = int(from.size());
  if (from.size() <= size_t(kModelTerms)) return pass;

  std::vector<cv::Point2f> tracked = to, lt, rt;
  std::vector<uint8_t> status;
  std::vector<float> error;
  cv::calcOpticalFlowPyrLK(left, right, from, tracked, status, error, {15, 15}, 1,
                           cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 30, 0.005),
                           cv::OPTFLOW_USE_INITIAL_FLOW);
  for (size_t i = 0; i < from.size(); ++i)
    if (status[i] && cv::norm(tracked[i] - to[i]) <= kMaxTrackShift) {
      lt.push_back(from[i]);
      rt.push_back(tracked[i]);
    }
  pass.refined = int(lt.size());
  if (lt.size() <= size_t(kModelTerms)) return pass;

  const std::vector<uint8_t> inliers = DyModelInliers(lt, rt, rect, o.ransac_px, &pass.model);
  for (size_t i = 0; i < lt.size(); ++i)
    if (inliers[i]) {
      pass.left.push_back(lt[i]);
      pass.right.push_back(rt[i]);
    }
  return pass;
}

// Shi-Tomasi corners, none weaker than min_strength (cv::goodFeaturesToTrack's
// own threshold is relative to the image's strongest corner: on noise alone
// it would keep noise).
std::vector<cv::Point2f> Corners(const cv::Mat& image, const cv::Mat& filled, const FeatureOptions& o) {
  cv::Mat strength;
  cv::cornerMinEigenVal(image, strength, 3);
  double strongest = 0;
  cv::minMaxLoc(strength, nullptr, &strongest, nullptr, nullptr, filled);
  std::vector<cv::Point2f> corners;
  if (!(strongest > o.min_strength)) return corners;
  cv::goodFeaturesToTrack(image, corners, o.max_corners, std::max(o.quality, o.min_strength / strongest),
                          o.min_distance_px, filled);
  return corners;
}

}  // namespace

cv::Mat FilledRegion(const Rectification& rect, bool left, double border_px) {
  const cv::Mat ones(rect.input_size, CV_8UC1, cv::Scalar(255));
  const auto& maps = (left ? rect.maps_left : rect.maps_right).front();
  cv::Mat filled;
  cv::remap(ones, filled, maps[0], maps[1], cv::INTER_NEAREST, cv::BORDER_CONSTANT, cv::Scalar(0));
  const int r = int(std::ceil(border_px));
  cv::erode(filled, filled, cv::getStructuringElement(cv::MORPH_ELLIPSE, {2 * r + 1, 2 * r + 1}), {-1, -1}, 1,
            cv::BORDER_CONSTANT, cv::Scalar(0));
  return filled;
}

RectifiedMatches MatchRectifiedPair(const cv::Mat& left, const cv::Mat& right, const cv::Mat& filled_left,
                                    const cv::Mat& filled_right, const Rectification& rect,
                                    const FeatureOptions& o) {
  RectifiedMatches out;
  std::vector<cv::Point2f> corners_left = Corners(left, filled_left, o);
  const std::vector<cv::Point2f> corners_right = Corners(right, filled_right, o);
  out.corners_left = int(corners_left.size());
  out.corners_right = int(corners_right.size());
  if (corners_left.size() < 5 || corners_right.size() < 5) return out;
  cv::cornerSubPix(left, corners_left, {5, 5}, {-1, -1},
                   cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 30, 0.01));
  const Described l = Describe(left, corners_left), r = Describe(right, corners_right);
  if (l.keys.empty() || r.keys.size() < 2) return out;

  // Pass 1: a narrow band of rows about dy = 0 or the whole band, whichever
  // keeps more inliers; pass 2: a narrow band about the dy field of pass 1's
  // inliers. In a narrow band a repetitive pattern (a board's squares)
  // offers one candidate only.
  auto no_field = [](const cv::Point2f&) { return 0.0; };
  Pass narrow = MatchPass(left, right, l, r, rect, o, no_field, std::min(kNarrowRows, o.search_rows));
  Pass wide = MatchPass(left, right, l, r, rect, o, no_field, o.search_rows);
  const Pass& first = narrow.left.size() >= wide.left.size() ? narrow : wide;
  if (first.model.empty()) return out;
  const cv::Mat model = first.model;
  Pass second = MatchPass(left, right, l, r, rect, o,
                          [&](const cv::Point2f& p) { return DyModelAt(rect, model, p); }, kNarrowRows);
  out.candidates = second.candidates;
  out.refined = second.refined;
  out.left = std::move(second.left);
  out.right = std::move(second.right);
  return out;
}

}  // namespace ws
