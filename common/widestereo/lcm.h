// widestereo's message types and their codecs, on top of the core
// (<widestereo/widestereo.h>, docs/library.md):
//
//   #include <widestereo/lcm.h>
//
//   const widestereo::stereo_calibration_t msg = ws::MessageFromRig(rig, utime);
//   ws::Validate(msg);  // throws ws::DecodeError
//
// Installed, CMake's find_package(widestereo COMPONENTS lcm) gives the target
// widestereo::lcm and pkg-config the package widestereo-lcm.
#pragma once

#include "lcm_io/image_codec.h"     // ImageToMat, MatToImage: image_t and cv::Mat
#include "lcm_io/validate.h"        // Validate: a decoded message's content
#include "rig/rig_message.h"        // RigFromMessage, MessageFromRig
#include "widestereo/messages.hpp"  // every LCM message type (lcm-gen)
#include "widestereo/widestereo.h"  // the core
