#include "sim/render.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <opencv2/aruco/charuco.hpp>
#include <opencv2/core/utility.hpp>
#include <opencv2/imgproc.hpp>

namespace ws {
namespace {

constexpr int64_t kMissRegion = std::numeric_limits<int64_t>::min();
constexpr int64_t kInvalidRegion = std::numeric_limits<int64_t>::min() + 1;
constexpr int64_t kBackRegion = std::numeric_limits<int64_t>::min() + 2;
constexpr int kSubRegions = 128;  // per square: whole, 4 ring strips, up to 9 x 9 marker cells

uint64_t SplitMix(uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

// floor for values well inside the int64 range (no libm call).
inline int64_t Floor(double x) {
  const int64_t i = int64_t(x);
  return i - (x < double(i));
}

}  // namespace

uint64_t MixSeed(std::initializer_list<uint64_t> values) {
  uint64_t h = 0x6a09e667f3bcc909ull;
  for (uint64_t v : values) h = SplitMix(h ^ SplitMix(v));
  return h;
}

// ---------------------------------------------------------------------------

BoardPattern::BoardPattern(const BoardSpec& board, const SimRendering& levels, bool front)
    : board_(board),
      black_(float(levels.black)),
      white_(float(levels.white)),
      background_(float(levels.background)),
      front_(front),
      inverse_square_(1 / board.square),
      squares_x_(board.cols + 1),
      squares_y_(board.rows + 1),
      marker_of_square_(size_t(squares_x_) * squares_y_, -1) {
  if (board.type != BoardType::charuco) return;
  const auto dictionary = cv::aruco::getPredefinedDictionary(board.dictionary);
  const auto charuco = cv::aruco::CharucoBoard::create(squares_x_, squares_y_, float(board.square),
                                                       float(board.marker), dictionary);
  // OpenCV's ChArUco frame has the board's outer corner at the origin; its
  // chessboard corner id k sits at ((k % cols + 1), (k / cols + 1)) squares,
  // which is where board_spec.h puts corner k plus one square in x and y.
  for (size_t m = 0; m < charuco->ids.size(); ++m) {
    const auto& p = charuco->objPoints[m];
    Marker marker;
    marker.bits_per_side = dictionary->markerSize;
    marker.bits = cv::aruco::Dictionary::getBitsFromByteList(
        dictionary->bytesList.rowRange(charuco->ids[m], charuco->ids[m] + 1), dictionary->markerSize);
    const double s = board.square;
    marker.origin = cv::Vec2d(p[0].x / s, p[0].y / s);
    const cv::Vec2d along_x(p[1].x - p[0].x, p[1].y - p[0].y), along_y(p[3].x - p[0].x, p[3].y - p[0].y);
    marker.side = cv::norm(along_x) / s;
    marker.axis_x = along_x / cv::norm(along_x);
    marker.axis_y = along_y / cv::norm(along_y);
    const double cx = (p[0].x + p[2].x) / 2 / s, cy = (p[0].y + p[2].y) / 2 / s;
    const int ix = int(std::floor(cx)), iy = int(std::floor(cy));
    if (ix >= 0 && iy >= 0 && ix < squares_x_ && iy < squares_y_) {
      marker_of_square_[size_t(iy) * squares_x_ + ix] = int(markers_.size());
      markers_.push_back(marker);
    }
  }
}

PatternSample BoardPattern::At(double u, double v) const {
  // Square units from the board's outer corner: squares span [0, squares_x) x [0, squares_y).
  const double su = u * inverse_square_ + 1, sv = v * inverse_square_ + 1;
  // Clamped first: the same square indices, and no overflow far away.
  const int iu = int(Floor(std::clamp(su, -2.0, squares_x_ + 1.0)));
  const int iv = int(Floor(std::clamp(sv, -2.0, squares_y_ + 1.0)));
  const int64_t square_region = (int64_t(iv + 2) * (squares_x_ + 4) + (iu + 2)) * kSubRegions;
  const bool on_board = iu >= 0 && iv >= 0 && iu < squares_x_ && iv < squares_y_;
  const bool on_margin = !on_board && iu >= -1 && iv >= -1 && iu <= squares_x_ && iv <= squares_y_;
  if (!on_board && !on_margin) return {background_, square_region};
  if (!front_) return {white_, kBackRegion};  // the back: one convex rectangle, board and margin
  if (on_margin) return {white_, square_region};
  if ((iu + iv) % 2 == 0) return {black_, square_region};
  const int m = marker_of_square_[size_t(iv) * squares_x_ + iu];
  if (m < 0) return {white_, square_region};
  const Marker& marker = markers_[m];
  const cv::Vec2d d(su - marker.origin[0], sv - marker.origin[1]);
  const double a = d.dot(marker.axis_x) / marker.side, b = d.dot(marker.axis_y) / marker.side;
  if (b < 0) return {white_, square_region + 1};  // the white ring around the marker, in 4 strips
  if (b >= 1) return {white_, square_region + 2};
  if (a < 0) return {white_, square_region + 3};
  if (a >= 1) return {white_, square_region + 4};
  const int cells = marker.bits_per_side + 2;
  const int ca = std::min(int(a * cells), cells - 1), cb = std::min(int(b * cells), cells - 1);
  const int64_t region = square_region + 5 + cb * cells + ca;
  if (ca == 0 || cb == 0 || ca == cells - 1 || cb == cells - 1) return {black_, region};
  return {marker.bits.at<uint8_t>(cb - 1, ca - 1) ? white_ : black_, region};
}

PatternSample BoardPattern::Miss() const { return {background_, kMissRegion}; }

// ---------------------------------------------------------------------------

DotWallPattern::DotWallPattern(double dot_size, double density, uint64_t seed, const SimRendering& levels)
    : inverse_size_(1 / dot_size),
      // P(h < threshold) = density for a uniform 64-bit h.
      threshold_(density >= 1 ? ~0ull : uint64_t(std::ldexp(density, 64))),
      seed_(SplitMix(seed)),
      black_(float(levels.black)),
      white_(float(levels.white)),
      background_(float(levels.background)) {}

bool DotWallPattern::Dark(int64_t iu, int64_t iv) const {
  const uint64_t h = SplitMix(seed_ + uint64_t(iu) * 0x9e3779b97f4a7c15ull + uint64_t(iv) * 0xc2b2ae3d27d4eb4full);
  return h < threshold_;
}

PatternSample DotWallPattern::At(double u, double v) const {
  const int64_t iu = Floor(std::clamp(u * inverse_size_, -1e9, 1e9));
  const int64_t iv = Floor(std::clamp(v * inverse_size_, -1e9, 1e9));
  return {Dark(iu, iv) ? black_ : white_, int64_t((uint64_t(iu) << 32) ^ uint64_t(uint32_t(iv)))};
}

bool DotWallPattern::Uniform(double u0, double u1, double v0, double v1, float* value) const {
  const double limit = 1e9;
  const int64_t iu0 = Floor(std::clamp(u0 * inverse_size_, -limit, limit));
  const int64_t iu1 = Floor(std::clamp(u1 * inverse_size_, -limit, limit));
  const int64_t iv0 = Floor(std::clamp(v0 * inverse_size_, -limit, limit));
  const int64_t iv1 = Floor(std::clamp(v1 * inverse_size_, -limit, limit));
  if (iu1 - iu0 > 2 || iv1 - iv0 > 2) return false;
  const bool dark = Dark(iu0, iv0);
  for (int64_t iv = iv0; iv <= iv1; ++iv)
    for (int64_t iu = iu0; iu <= iu1; ++iu)
      if (Dark(iu, iv) != dark) return false;
  *value = dark ? black_ : white_;
  return true;
}

PatternSample DotWallPattern::Miss() const { return {background_, kMissRegion}; }

// ---------------------------------------------------------------------------

namespace {

// Every vertex ray meets each plane k at p_k = M_k r (plane coordinates
// (p0 / p2, p1 / p2), ahead along the ray when p2 > 0, at range 1 / p2): the
// ray sees the plane it meets first, the largest p2. One plane: that plane
// or a miss. A box seen from inside: the face the ray leaves it through.
template <class Pattern>
cv::Mat RenderPlanesWith(const RayMap& rays, const std::vector<cv::Matx33d>& planes_to_camera,
                         const std::vector<const Pattern*>& patterns, int supersample) {
  const int width = rays.vertex_cols() - 1, height = rays.vertex_rows() - 1;
  const size_t planes = planes_to_camera.size();
  std::vector<cv::Matx33d> M;
  for (const cv::Matx33d& H : planes_to_camera) M.push_back(H.inv());
  const int n = std::max(1, supersample);
  std::vector<double> offsets(n);
  for (int k = 0; k < n; ++k) offsets[k] = (k + 0.5) / n;
  const PatternSample miss = patterns.front()->Miss();
  cv::Mat image(height, width, CV_32FC1);

  // The plane a ray sees among the plane points q[0..planes), -1 for none.
  auto nearest = [&](const cv::Vec3d* q) {
    int best = -1;
    for (size_t k = 0; k < planes; ++k)
      if (q[k][2] > 0 && (best < 0 || q[k][2] > q[best][2])) best = int(k);
    return best;
  };
  auto sample = [&](const cv::Vec3d* q, int plane) {
    return plane >= 0 ? patterns[size_t(plane)]->At(q[plane][0] / q[plane][2], q[plane][1] / q[plane][2]) : miss;
  };

  cv::parallel_for_(cv::Range(0, height), [&](const cv::Range& range) {
    const int cols = width + 1;
    const int vertex_rows = range.end - range.start + 1;
    const size_t vertices = size_t(vertex_rows) * cols;
    std::vector<cv::Vec3d> p(vertices * planes);  // vertex k's plane points at p[k * planes ...]
    std::vector<PatternSample> s(vertices);
    std::vector<int> plane(vertices);
    std::vector<uint8_t> valid(vertices);
    std::vector<cv::Vec3d> q(planes);
    for (int j = 0; j < vertex_rows; ++j)
      for (int i = 0; i < cols; ++i) {
        const size_t k = size_t(j) * cols + i;
        const cv::Vec3f& r = rays.Ray(i, range.start + j);
        valid[k] = RayMap::IsRay(r);
        for (size_t m = 0; m < planes; ++m) p[k * planes + m] = M[m] * cv::Vec3d(r[0], r[1], r[2]);
        plane[k] = nearest(&p[k * planes]);
        s[k] = valid[k] ? sample(&p[k * planes], plane[k]) : PatternSample{0, kInvalidRegion};
      }
    for (int y = range.start; y < range.end; ++y) {
      float* out = image.ptr<float>(y);
      const size_t row = size_t(y - range.start) * cols;
      for (int x = 0; x < width; ++x) {
        const size_t k00 = row + x, k10 = k00 + 1, k01 = k00 + cols, k11 = k01 + 1;
        if (!valid[k00] || !valid[k10] || !valid[k01] || !valid[k11]) {
          out[x] = 0;
          continue;
        }
        const int64_t region = s[k00].region;
        const int k = plane[k00];
        const bool one_plane = plane[k10] == k && plane[k01] == k && plane[k11] == k;
        if (one_plane && s[k10].region == region && s[k01].region == region && s[k11].region == region) {
          out[x] = s[k00].value;
          continue;
        }
        if (one_plane && k >= 0) {
          const cv::Vec3d &p00 = p[k00 * planes + k], &p10 = p[k10 * planes + k], &p01 = p[k01 * planes + k],
                          &p11 = p[k11 * planes + k];
          const double u[4] = {p00[0] / p00[2], p10[0] / p10[2], p01[0] / p01[2], p11[0] / p11[2]};
          const double v[4] = {p00[1] / p00[2], p10[1] / p10[2], p01[1] / p01[2], p11[1] / p11[2]};
          float value = 0;
          if (patterns[size_t(k)]->Uniform(*std::min_element(u, u + 4), *std::max_element(u, u + 4),
                                           *std::min_element(v, v + 4), *std::max_element(v, v + 4), &value)) {
            out[x] = value;
            continue;
          }
        }
        double sum = 0;
        for (int sy = 0; sy < n; ++sy) {
          const double b = offsets[sy];
          for (int sx = 0; sx < n; ++sx) {
            const double a = offsets[sx];
            for (size_t m = 0; m < planes; ++m) {
              const cv::Vec3d left = (1 - b) * p[k00 * planes + m] + b * p[k01 * planes + m];
              const cv::Vec3d right = (1 - b) * p[k10 * planes + m] + b * p[k11 * planes + m];
              q[m] = (1 - a) * left + a * right;
            }
            sum += sample(q.data(), nearest(q.data())).value;
          }
        }
        out[x] = float(sum / (n * n));
      }
    }
  });
  return image;
}

}  // namespace

cv::Mat RenderPlane(const RayMap& rays, const cv::Matx33d& plane_to_camera, const PlanePattern& pattern,
                    int supersample) {
  // The patterns the simulator knows are final classes: called directly, no virtual call per sample.
  if (const auto* board = dynamic_cast<const BoardPattern*>(&pattern))
    return RenderPlanesWith<BoardPattern>(rays, {plane_to_camera}, {board}, supersample);
  if (const auto* wall = dynamic_cast<const DotWallPattern*>(&pattern))
    return RenderPlanesWith<DotWallPattern>(rays, {plane_to_camera}, {wall}, supersample);
  return RenderPlanesWith<PlanePattern>(rays, {plane_to_camera}, {&pattern}, supersample);
}

cv::Mat RenderRoom(const RayMap& rays, const std::vector<cv::Matx33d>& faces_to_camera,
                   const std::vector<const DotWallPattern*>& patterns, int supersample) {
  CV_Assert(!faces_to_camera.empty() && faces_to_camera.size() == patterns.size());
  return RenderPlanesWith<DotWallPattern>(rays, faces_to_camera, patterns, supersample);
}

cv::Mat FinishImage(const cv::Mat& linear, const SimRendering& rendering, uint64_t noise_seed) {
  cv::Mat grey;
  if (rendering.blur_sigma > 0)
    cv::GaussianBlur(linear, grey, cv::Size(), rendering.blur_sigma, rendering.blur_sigma, cv::BORDER_REFLECT);
  else
    grey = linear.clone();
  if (rendering.gamma != 1.0) {
    cv::max(grey, 0.0, grey);
    grey *= 1.0 / 255;
    cv::pow(grey, 1.0 / rendering.gamma, grey);
    grey *= 255.0;
  }
  if (rendering.noise_sigma > 0) {
    cv::Mat noise(grey.size(), CV_32FC1);
    cv::RNG rng(noise_seed);
    rng.fill(noise, cv::RNG::NORMAL, 0, rendering.noise_sigma);
    grey += noise;
  }
  cv::Mat out;
  grey.convertTo(out, CV_8UC1);  // rounds and saturates
  return out;
}

}  // namespace ws
