// The simulator's frames served by fake GigE Vision cameras
// (stereo-fake-cameras --frames sim:CONFIG.yaml, make demo): the real
// GenICam path carries the simulated rig's images.
#pragma once

#include <string>

#include "fake_cameras/frame_providers.h"

namespace ws {

// Frame k of the provider is simulator frame k modulo the scene's frame
// count. Every frame is rendered up front (in parallel), so serving costs a
// copy. `spec` is what follows "sim:" in stereo-capture's --source
// (CONFIG.yaml[?truth=FILE]); the ground truth is written the same way.
// Throws SimConfigError or std::invalid_argument.
StereoFrameProvider SimulatorFrames(const std::string& spec);

}  // namespace ws
