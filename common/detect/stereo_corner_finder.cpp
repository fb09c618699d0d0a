#include "detect/stereo_corner_finder.h"

#include <algorithm>
#include <string>

#include <opencv2/imgproc.hpp>

#include "lcm_io/image_codec.h"

namespace ws {
namespace {

// The detectors want 8-bit grey: colour is converted, and deeper images are
// stretched from their darkest to their brightest pixel.
cv::Mat ToGray8(const cv::Mat& image) {
  cv::Mat gray;
  if (image.type() == CV_8UC1) return image;
  if (image.type() == CV_8UC3) {
    cv::cvtColor(image, gray, cv::COLOR_BGR2GRAY);
    return gray;
  }
  cv::normalize(image, gray, 0, 255, cv::NORM_MINMAX, CV_8UC1);
  return gray;
}

// libjpeg decodes a JPEG that was cut short without an error (it fills the
// rest with grey), so ImageToMat accepts it; the cut shows as a payload that
// does not end with the end-of-image marker (after any zero padding).
void RequireCompleteJpeg(const widestereo::image_t& image) {
  if (image.pixelformat != widestereo::image_t::PIXEL_FORMAT_MJPEG) return;
  auto end = image.data.end();
  while (end != image.data.begin() && *(end - 1) == 0) --end;
  if (end - image.data.begin() < 2 || end[-2] != 0xFF || end[-1] != 0xD9)
    throw DecodeError("image_t: JPEG payload is cut short (no end-of-image marker)");
}

bool ShowsBoard(cv::Size image, const BoardSpec& board) {
  constexpr int kMinPixelsPerSquare = 2;
  const int short_side = kMinPixelsPerSquare * (std::min(board.cols, board.rows) + 1);
  const int long_side = kMinPixelsPerSquare * (std::max(board.cols, board.rows) + 1);
  return std::min(image.width, image.height) >= short_side &&
         std::max(image.width, image.height) >= long_side;
}

}  // namespace

StereoCornerFinder::StereoCornerFinder(BoardSpec board, ChessboardMethod method, BoardSearch search,
                                       int64_t max_image_pixels)
    : board_(std::move(board)),
      detector_(MakeCornerDetector(board_, method, search)),
      max_image_pixels_(max_image_pixels) {}

widestereo::stereo_corners_t StereoCornerFinder::Find(const widestereo::stereo_frame_t& frame,
                                                      int* unrefined) const {
  widestereo::stereo_corners_t corners{};
  corners.utime = frame.utime;
  corners.frame_id = frame.frame_id;
  int left_unrefined = 0, right_unrefined = 0;
  corners.left = FindInImage(frame.left, &left_unrefined);
  // A one-camera rig's frame has no right image: no corners and no size.
  corners.right = IsNoImage(frame.right) ? NoCamera() : FindInImage(frame.right, &right_unrefined);
  if (unrefined) *unrefined = left_unrefined + right_unrefined;
  return corners;
}

widestereo::camera_corners_t StereoCornerFinder::NoCamera() const {
  widestereo::camera_corners_t none{};
  none.board_id = board_.id;
  return none;
}

widestereo::camera_corners_t StereoCornerFinder::FindInImage(const widestereo::image_t& image,
                                                              int* unrefined) const {
  RequireCompleteJpeg(image);
  const cv::Mat gray = ToGray8(ImageToMat(image, max_image_pixels_));
  if (!ShowsBoard(gray.size(), board_))
    throw DecodeError("a " + std::to_string(gray.cols) + "x" + std::to_string(gray.rows) +
                      " image is too small to show board " + board_.id);
  const BoardCorners found = detector_->Detect(gray);
  if (unrefined) *unrefined = found.unrefined;
  widestereo::camera_corners_t out;
  out.board_id = board_.id;
  out.image_width = gray.cols;
  out.image_height = gray.rows;
  out.n = int32_t(found.ids.size());
  out.ids = found.ids;
  for (size_t i = 0; i < found.ids.size(); ++i) {
    const cv::Point3d object = board_.ObjectPoint(found.ids[i]);
    out.image_points.push_back({found.points[i].x, found.points[i].y});
    out.object_points.push_back({object.x, object.y, object.z});
  }
  return out;
}

}  // namespace ws
