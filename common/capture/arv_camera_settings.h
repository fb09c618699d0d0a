// How stereo-capture drives a pair of GenICam cameras through Aravis, and the
// loader of those settings from the rig's YAML file (config/rig/).
#pragma once

#include <stdexcept>
#include <string>

namespace ws {

// A rig file that is missing a field, has one of the wrong type, or a value
// out of range. The message names the file, the field and the reason.
struct RigConfigError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

enum class TriggerMode {
  software,  // one software trigger to both cameras per pair
  free_run,  // both cameras run at frame_rate_hz; frames are paired by time
};

// "software" or "free-run".
std::string TriggerModeName(TriggerMode mode);

// Which timestamps decide that two frames make a pair.
enum class PairingClock {
  host,    // when the frames began to arrive here: works for any cameras
  camera,  // the cameras' own: only for cameras on one clock (PTP, fake cameras)
};

// "host" or "camera".
std::string PairingClockName(PairingClock clock);

// The defaults are the example values. In a rig file they are the map
// `aravis` (OpenCV needs the first line exactly as shown; every field is
// required, unknown fields are errors; other top-level maps are ignored; text
// followed by a comment must be quoted, or OpenCV reads the comment as text):
//
//   %YAML:1.0
//   aravis:
//     pixel_format: "Mono8"     # Mono8 | Mono16 | RGB8 | BGR8
//     exposure_us: 10000
//     gain_db: 0.0
//     frame_rate_hz: 10.0       # pairs per second: trigger rate, or the cameras' rate in free-run
//     packet_size: 0            # GigE Vision packet size in bytes; 0: negotiate with the camera
//     trigger: "software"       # software | free-run
//     pairing_tolerance_ms: 20  # largest time between the two frames of a pair
//     pairing_clock: "host"     # host | camera
//
// A camera that lacks the exposure, gain or frame-rate feature is used
// without it (with a warning); one that lacks the pixel format or a software
// trigger cannot be used.
struct ArvCameraSettings {
  std::string pixel_format = "Mono8";
  double exposure_us = 10000;
  double gain_db = 0;
  double frame_rate_hz = 10;
  int packet_size = 0;
  TriggerMode trigger = TriggerMode::software;
  double pairing_tolerance_ms = 20;
  PairingClock pairing_clock = PairingClock::host;
};

// Throws RigConfigError "field 'NAME': REASON" for the first bad value. The
// pairing tolerance must stay under half a frame period, or pairs are ambiguous.
void ValidateArvCameraSettings(const ArvCameraSettings& settings);

// Reads and validates the `aravis` map of a rig file. Throws RigConfigError
// "PATH: field 'aravis.NAME': REASON" (or "PATH: REASON" when the file is bad).
ArvCameraSettings LoadArvCameraSettings(const std::string& path);

}  // namespace ws
