#include "detect/synthetic_view.h"

#include <cmath>

#include <opencv2/aruco/charuco.hpp>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

namespace ws {
namespace {

constexpr double kDark = 30, kLight = 220, kBackground = 125;
constexpr int kTexelsPerSquare = 120;

double Radians(double degrees) { return degrees * CV_PI / 180; }

// Grey level of the board plane at (u, v), in squares from the board's outer
// corner (the board's squares span [0, COLS+1] x [0, ROWS+1]).
class BoardSurface {
 public:
  explicit BoardSurface(const BoardSpec& board) : board_(board) {
    if (board.type != BoardType::charuco) return;
    const auto charuco = cv::aruco::CharucoBoard::create(
        board.cols + 1, board.rows + 1, float(board.square), float(board.marker),
        cv::aruco::getPredefinedDictionary(board.dictionary));
    charuco->draw(cv::Size((board.cols + 1) * kTexelsPerSquare, (board.rows + 1) * kTexelsPerSquare),
                  texture_, 0, 1);
  }

  double At(double u, double v) const {
    const int squares_x = board_.cols + 1, squares_y = board_.rows + 1;
    if (u >= 0 && v >= 0 && u < squares_x && v < squares_y) {
      if (!texture_.empty())
        return kDark + (kLight - kDark) / 255 *
                           texture_.at<uint8_t>(int(v * kTexelsPerSquare), int(u * kTexelsPerSquare));
      return (int(u) + int(v)) % 2 == 0 ? kDark : kLight;
    }
    return u >= -1 && v >= -1 && u < squares_x + 1 && v < squares_y + 1 ? kLight : kBackground;
  }

 private:
  const BoardSpec& board_;
  cv::Mat texture_;
};

}  // namespace

cv::Matx33d BoardToImage(const BoardSpec& board, const BoardPose& pose, cv::Size image_size) {
  const double f = image_size.width;
  const cv::Matx33d K(f, 0, (image_size.width - 1) / 2.0, 0, f, (image_size.height - 1) / 2.0, 0, 0, 1);
  const double width = (board.cols + 3) * board.square;  // squares plus the margin
  const double distance = f * width / (pose.fill * image_size.width);
  cv::Matx33d R;
  cv::Rodrigues(cv::Vec3d(0, 0, Radians(pose.roll_deg)), R);
  cv::Matx33d tilt_x, tilt_y;
  cv::Rodrigues(cv::Vec3d(Radians(pose.tilt_x_deg), 0, 0), tilt_x);
  cv::Rodrigues(cv::Vec3d(0, Radians(pose.tilt_y_deg), 0), tilt_y);
  R = tilt_y * tilt_x * R;
  const cv::Vec3d centre((board.cols - 1) * board.square / 2, (board.rows - 1) * board.square / 2, 0);
  const cv::Vec3d t = cv::Vec3d(pose.shift.x * image_size.width * distance / f,
                                pose.shift.y * image_size.height * distance / f, distance) - R * centre;
  const cv::Matx33d extrinsic(R(0, 0), R(0, 1), t[0], R(1, 0), R(1, 1), t[1], R(2, 0), R(2, 1), t[2]);
  return K * extrinsic;
}

SyntheticView RenderBoard(const BoardSpec& board, const cv::Matx33d& board_to_image,
                          const RenderSettings& settings) {
  const BoardSurface surface(board);
  const cv::Matx33d image_to_squares =
      cv::Matx33d(1 / board.square, 0, 1, 0, 1 / board.square, 1, 0, 0, 1) * board_to_image.inv();
  const int n = settings.supersample;
  cv::Mat grey(settings.size, CV_32FC1);
  cv::parallel_for_(cv::Range(0, grey.rows), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y)
      for (int x = 0; x < grey.cols; ++x) {
        double sum = 0;
        for (int sy = 0; sy < n; ++sy)
          for (int sx = 0; sx < n; ++sx) {
            const cv::Vec3d p = image_to_squares *
                                cv::Vec3d(x - 0.5 + (sx + 0.5) / n, y - 0.5 + (sy + 0.5) / n, 1);
            sum += surface.At(p[0] / p[2], p[1] / p[2]);
          }
        grey.at<float>(y, x) = float(sum / (n * n) * std::pow(settings.light_falloff, -double(x) / grey.cols));
      }
  });
  if (settings.blur_sigma > 0) cv::GaussianBlur(grey, grey, cv::Size(), settings.blur_sigma);
  if (settings.noise_sigma > 0) {
    cv::Mat noise(grey.size(), CV_32FC1);
    cv::RNG rng(settings.seed);
    rng.fill(noise, cv::RNG::NORMAL, 0, settings.noise_sigma);
    grey += noise;
  }
  SyntheticView view;
  grey.convertTo(view.image, CV_8UC1);  // rounds and saturates
  for (int id = 0; id < board.corner_count(); ++id) {
    const cv::Point3d object = board.ObjectPoint(id);
    const cv::Vec3d p = board_to_image * cv::Vec3d(object.x, object.y, 1);
    view.corners.emplace_back(p[0] / p[2], p[1] / p[2]);
  }
  return view;
}

}  // namespace ws
