#include "rig/publish_calibration.h"

#include "lcm_io/channels.h"

namespace ws {

void PublishCalibration(Process& process, const widestereo::stereo_calibration_t& msg) {
  process.Publish(channel::kStereoCalibration, msg);
}

}  // namespace ws
