#include "calib/node/corners_message.h"

#include <algorithm>

namespace ws::calib {

BoardView ToBoardView(const widestereo::camera_corners_t& msg) {
  BoardView view;
  const int n = std::max(0, msg.n);
  if (msg.ids.size() != size_t(n) || msg.object_points.size() != size_t(n) || msg.image_points.size() != size_t(n))
    throw CalibrationError("corners message: n = " + std::to_string(msg.n) + " but " + std::to_string(msg.ids.size()) +
                           " ids, " + std::to_string(msg.image_points.size()) + " image and " +
                           std::to_string(msg.object_points.size()) + " object points");
  view.ids.reserve(n);
  view.object.reserve(n);
  view.image.reserve(n);
  for (int i = 0; i < n; ++i) {
    view.ids.push_back(msg.ids[i]);
    view.object.emplace_back(msg.object_points[i][0], msg.object_points[i][1],
                             msg.object_points[i][2]);
    view.image.emplace_back(msg.image_points[i][0], msg.image_points[i][1]);
  }
  return view;
}

widestereo::camera_corners_t ToCornersMessage(const BoardView& view, const std::string& board_id,
                                              int image_width, int image_height) {
  widestereo::camera_corners_t msg;
  msg.board_id = board_id;
  msg.image_width = image_width;
  msg.image_height = image_height;
  msg.n = view.size();
  for (int i = 0; i < view.size(); ++i) {
    msg.ids.push_back(view.ids[i]);
    msg.image_points.push_back({view.image[i].x(), view.image[i].y()});
    msg.object_points.push_back({view.object[i].x(), view.object[i].y(), view.object[i].z()});
  }
  return msg;
}

namespace {

void TakeImageSize(CameraData& camera, const widestereo::camera_corners_t& msg) {
  const bool unsized = camera.image_width == 0 && camera.image_height == 0;
  if (msg.n <= 0) {  // an image without the board still says the camera is there
    if (unsized && msg.image_width > 0 && msg.image_height > 0) {
      camera.image_width = msg.image_width;
      camera.image_height = msg.image_height;
    }
    return;
  }
  if (unsized) {
    camera.image_width = msg.image_width;
    camera.image_height = msg.image_height;
  } else if (camera.image_width != msg.image_width || camera.image_height != msg.image_height) {
    throw CalibrationError(camera.name + " corners of a " + std::to_string(msg.image_width) + "x" +
                           std::to_string(msg.image_height) + " image, but earlier views were " +
                           std::to_string(camera.image_width) + "x" +
                           std::to_string(camera.image_height));
  }
}

}  // namespace

void AddStereoCorners(StereoData& data, const widestereo::stereo_corners_t& msg) {
  TakeImageSize(data.left, msg.left);
  TakeImageSize(data.right, msg.right);
  data.Add(ToBoardView(msg.left), ToBoardView(msg.right));
}

}  // namespace ws::calib
