// One open connection to a GenICam camera, configured and acquiring from
// construction to destruction. AravisCamera's control thread makes it, sends
// its triggers, checks it and destroys it; another thread may Pop() and
// Push() buffers at the same time.
#pragma once

#include <arv.h>

#include <atomic>
#include <chrono>
#include <functional>
#include <string>
#include <vector>

#include "capture/arv_camera_settings.h"
#include "capture/gobject_ptr.h"

namespace ws {

class ArvSession {
 public:
  // Opens camera `id` (any name arv_camera_new accepts: device id such as
  // "Aravis-Fake-LEFT", IP address, MAC), applies the settings and starts
  // acquiring into n_buffers buffers. Settings the camera lacks are skipped
  // and described in *warnings. on_control_lost is called from an Aravis
  // thread when the camera stops answering or grants control to no one.
  // Throws CameraError.
  ArvSession(const std::string& id, const ArvCameraSettings& settings, int n_buffers,
             std::function<void()> on_control_lost, std::vector<std::string>* warnings);
  // Stops acquisition (unless marked lost) and closes the camera. For a camera
  // that has gone this takes Aravis's control timeouts, several seconds.
  ~ArvSession();
  ArvSession(const ArvSession&) = delete;
  ArvSession& operator=(const ArvSession&) = delete;

  // The camera has gone: do not talk to it any more when closing.
  void MarkLost() { lost_ = true; }
  bool control_lost() const { return control_lost_; }
  // "ID: VENDOR MODEL (serial S) at ADDRESS, WxH FORMAT, ..." for the log.
  const std::string& description() const { return description_; }

  // Each returns "" on success, or why it failed.
  std::string SoftwareTrigger();
  // Whether the camera still answers and still has us as its controller (a
  // camera that restarted answers, but to no one in particular).
  std::string CheckInControl();

  // The next filled buffer, or nullptr after `timeout`; give it back with Push().
  ArvBuffer* Pop(std::chrono::microseconds timeout);
  void Push(ArvBuffer* buffer) { arv_stream_push_buffer(stream_.get(), buffer); }

 private:
  static void OnControlLost(ArvDevice* device, gpointer self);
  void Close();
  void Configure(const ArvCameraSettings& settings, std::vector<std::string>* warnings);
  void ConfigureGigE(const ArvCameraSettings& settings, std::vector<std::string>* warnings);
  void CreateStream(int n_buffers, std::vector<std::string>* warnings);
  std::string Describe() const;

  const std::string id_;
  std::function<void()> on_control_lost_;
  GObjectPtr<ArvCamera> camera_;
  GObjectPtr<ArvStream> stream_;
  gulong control_lost_handler_ = 0;
  std::atomic<bool> control_lost_{false};
  std::atomic<bool> lost_{false};
  std::string address_;  // of a GigE Vision camera, "" otherwise
  std::string description_;
};

}  // namespace ws
