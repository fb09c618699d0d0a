#include "detect/thumbnail_frame.h"

#include <algorithm>

#include <opencv2/imgproc.hpp>

#include "lcm_io/image_codec.h"

namespace ws {
namespace {

widestereo::image_t Thumbnail(const widestereo::image_t& image, int64_t utime) {
  const cv::Mat full = ImageView(image);
  if (full.cols <= kThumbnailWidth) return MatToImage(full, utime);  // never enlarged: a narrow image stays small
  cv::Mat small;
  cv::resize(full, small, {kThumbnailWidth, std::max(1, int(int64_t(full.rows) * kThumbnailWidth / full.cols))}, 0,
             0, cv::INTER_AREA);
  return MatToImage(small, utime);
}

}  // namespace

widestereo::stereo_frame_t ThumbnailFrame(const widestereo::stereo_frame_t& frame,
                                          const widestereo::stereo_corners_t& corners) {
  widestereo::stereo_frame_t thumbnail{};
  thumbnail.frame_id = frame.frame_id;
  thumbnail.utime = frame.utime;
  thumbnail.left = Thumbnail(corners.left.n > 0 ? frame.left : frame.right, frame.utime);
  thumbnail.right = NoImage(frame.utime);
  return thumbnail;
}

}  // namespace ws
