// A simulated stereo rig served as two fake GigE Vision cameras
// (stereo-fake-cameras, tests, `make demo`): stereo-capture reads it with
// --source aravis:Aravis-Fake-LEFT,Aravis-Fake-RIGHT like a real rig.
//
// The frame index given to the provider is the simulated moment: frames the
// two cameras expose within same_moment_ms get the same index on both sides,
// each later moment the next one (see ExposureIndex). Read with
// pairing_clock: camera and pairing_tolerance_ms equal to same_moment_ms, the
// capture's pairs always show one moment (config/rig/fake-gige.yaml).
#pragma once

#include <string>

#include <opencv2/core.hpp>

#include "capture/camera_frame.h"
#include "fake_cameras/exposure_index.h"
#include "fake_cameras/fake_gige_camera.h"
#include "fake_cameras/frame_providers.h"

namespace ws {

struct FakeStereoCamerasConfig {
  std::string left_address = "127.0.0.1";
  std::string right_address = "127.0.0.2";  // see gige_address.h
  std::string left_serial = "LEFT";
  std::string right_serial = "RIGHT";
  cv::Size size;  // empty: the size of the provider's first left image
  std::string pixel_format = "Mono8";
  double same_moment_ms = 40;  // under half the frame period
  GvcpPortClaim::Waiting waiting;  // told when a camera waits for its address
};

class FakeStereoCameras {
 public:
  // Starts both cameras; throws CameraError (see FakeGigeCamera).
  FakeStereoCameras(const FakeStereoCamerasConfig& config, StereoFrameProvider provider);

  FakeGigeCamera& camera(Side side) { return side == Side::left ? left_ : right_; }
  // "Aravis-Fake-LEFT,Aravis-Fake-RIGHT": what follows "aravis:" in stereo-capture's --source.
  std::string camera_ids() const;

 private:
  FakeGigeCameraConfig CameraConfig(const FakeStereoCamerasConfig& config, Side side);
  cv::Mat Frame(Side side, const FakeGigeCamera::FrameRequest& frame);

  const StereoFrameProvider provider_;
  ExposureIndex index_;
  cv::Size size_;
  FakeGigeCamera left_;  // after provider_ and index_, which its thread uses
  FakeGigeCamera right_;
};

}  // namespace ws
