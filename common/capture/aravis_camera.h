// One GenICam camera read through Aravis that keeps itself connected.
//
// A control thread opens and configures the camera, sends its software
// triggers, and watches it: when it stops answering (a trigger fails,
// Aravis's control-lost signal, or no frame for stall_timeout and then no
// answer to a register read) or when it restarted (it answers but no longer
// has us as controller), the connection is dropped and reopened every
// retry_interval until the camera is back. Aravis 0.8 gives up on a silent
// camera only after 5 tries of 500 ms, so a loss takes about 2.5 s to notice.
// Closing a camera that has gone takes Aravis several seconds of control
// timeouts too; that happens on a thread of its own, so reopening starts at
// once. The first frame after each (re)connection is dropped: it often comes
// late or incomplete (Aravis sizes the stream's socket only when it arrives).
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "capture/arv_camera_settings.h"
#include "capture/camera_frame.h"

namespace ws {

struct AravisCameraOptions {
  int n_buffers = 4;                              // frames Aravis can hold for us
  std::chrono::milliseconds stall_timeout{1000};  // no frame this long: check the camera
  std::chrono::milliseconds retry_interval{500};  // between attempts to reopen it
};

enum class GrabStatus {
  frame,         // a complete frame
  incomplete,    // a buffer arrived with packets missing; no frame
  timeout,       // connected, but nothing arrived in time
  disconnected,  // the camera is away
};

struct GrabResult {
  GrabStatus status = GrabStatus::timeout;
  CameraFrame frame;  // set when status is frame
};

struct CameraCounters {
  uint64_t completed = 0;   // complete frames delivered
  uint64_t incomplete = 0;  // buffers that arrived with packets missing
  uint64_t lost = 0;        // frame ids skipped: frames that never arrived at all
  uint64_t timeouts = 0;    // Grabs that waited on a connected camera and got nothing
  uint64_t reconnects = 0;  // connections re-established after the camera went away
};

class AravisCamera {
 public:
  // Starts connecting to `id` (any name arv_camera_new accepts: device id such
  // as "Aravis-Fake-LEFT", IP address, MAC) in the background; an absent
  // camera is not an error, it is waited for.
  AravisCamera(std::string id, ArvCameraSettings settings, AravisCameraOptions options = {});
  ~AravisCamera();
  AravisCamera(const AravisCamera&) = delete;
  AravisCamera& operator=(const AravisCamera&) = delete;

  const std::string& id() const;
  bool connected() const;
  bool WaitConnected(std::chrono::milliseconds timeout);

  // Asks for one software trigger; the control thread sends it at once.
  // Ignored while disconnected.
  void RequestTrigger();

  // The next frame, waiting up to `timeout` (0: only what has arrived). One
  // thread at a time.
  GrabResult Grab(std::chrono::milliseconds timeout);

  CameraCounters counters() const;
  // The last connection failure or loss ("" if none yet); it stays after a reconnect.
  std::string last_error() const;
  // What happened since the last call, oldest first, for the log: connections
  // (with the camera's description), losses, settings the camera lacks, and
  // the first failure of each series of reconnection attempts.
  std::vector<std::string> TakeEvents();

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ws
