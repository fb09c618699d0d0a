// Where the images of a simulated stereo rig come from (what the fake cameras
// of FakeStereoCameras serve): a function from frame index and side to image.
// It is called from both cameras' threads at once, so it must be thread-safe.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include <opencv2/core.hpp>

namespace ws {

// The image of frame `frame_index` (0, 1, 2, ...) for the left or right
// camera: CV_8U or CV_16U, 1 or 3 channels (colour in BGR order), any size.
using StereoFrameProvider = std::function<cv::Mat(int64_t frame_index, bool left)>;

// A textured wall parallel to the cameras, sliding sideways by 4 pixels per
// frame; the right camera sees it 32 pixels further left (disparity 32). Gray.
StereoFrameProvider MovingTestPattern(cv::Size size);

// The same two image files for every frame. Throws CameraError if one cannot be read.
StereoFrameProvider ImagePairFrames(const std::string& left_path, const std::string& right_path);

// The pairs left*/right* of a directory, matched by the rest of the name
// (left01.jpg with right01.jpg), in name order, over and over. Images are read
// when served. Throws CameraError when there is no pair or a name has no match.
StereoFrameProvider ImageDirectoryFrames(const std::string& directory);

// "pattern" (MovingTestPattern of pattern_size), "pair:LEFT,RIGHT",
// "dir:PATH" or "sim:CONFIG.yaml" (sim_frames.h). Throws CameraError (and
// the simulator's errors for sim:).
StereoFrameProvider MakeFrameProvider(const std::string& spec, cv::Size pattern_size);

}  // namespace ws
