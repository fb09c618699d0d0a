#include "calib/calib_publish.h"

#include "lcm_io/channels.h"

namespace ws::calib {

void PublishCalibration(Process& process, const widestereo::stereo_calibration_t& msg) {
  process.Publish(channel::kStereoCalibration, msg);
}

}  // namespace ws::calib
