#include "fake_cameras/fake_stereo_cameras.h"

#include <cmath>
#include <utility>

#include "capture/camera_error.h"

namespace ws {
namespace {

int64_t SameMomentNs(double same_moment_ms) {
  if (!(same_moment_ms > 0)) throw CameraError("same_moment_ms must be > 0");
  return std::llround(same_moment_ms * 1e6);
}

cv::Size FirstImageSize(const StereoFrameProvider& provider) {
  const cv::Mat first = provider(0, true);
  if (first.empty()) throw CameraError("the frame provider gave no first image");
  return first.size();
}

}  // namespace

FakeStereoCameras::FakeStereoCameras(const FakeStereoCamerasConfig& config,
                                     StereoFrameProvider provider)
    : provider_(std::move(provider)),
      index_(SameMomentNs(config.same_moment_ms)),
      size_(config.size.empty() ? FirstImageSize(provider_) : config.size),
      left_(CameraConfig(config, Side::left),
            [this](const FakeGigeCamera::FrameRequest& frame) { return Frame(Side::left, frame); }),
      right_(CameraConfig(config, Side::right), [this](const FakeGigeCamera::FrameRequest& frame) {
        return Frame(Side::right, frame);
      }) {}

cv::Mat FakeStereoCameras::Frame(Side side, const FakeGigeCamera::FrameRequest& frame) {
  return provider_(index_.Assign(side, frame.timestamp_ns, frame.first_of_stream),
                   side == Side::left);
}

FakeGigeCameraConfig FakeStereoCameras::CameraConfig(const FakeStereoCamerasConfig& config,
                                                     Side side) {
  FakeGigeCameraConfig camera;
  camera.address = side == Side::left ? config.left_address : config.right_address;
  camera.serial = side == Side::left ? config.left_serial : config.right_serial;
  camera.size = size_;
  camera.pixel_format = config.pixel_format;
  camera.waiting = config.waiting;
  return camera;
}

std::string FakeStereoCameras::camera_ids() const {
  return left_.device_id() + "," + right_.device_id();
}

}  // namespace ws
