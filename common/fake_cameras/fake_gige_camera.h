// A real GigE Vision camera, served from this process by Aravis's simulator
// (ArvGvFakeCamera), whose images come from a callback.
//
// Clients find it by discovery as "Aravis-Fake-SERIAL" or open it by address;
// it speaks GVCP on UDP port 3956 of its address and streams GVSP, so the
// whole GenICam path of a client is exercised. It offers Mono8, Mono16 and
// RGB8 (and Aravis's Bayer formats, which it serves black), any size up to
// its sensor (the size it starts with), frame rates to 1000 Hz, packets of
// 220 to 16404 bytes (it cannot negotiate: it stays at 1400 unless set),
// free-run and software trigger; it has ExposureTimeAbs and GainRaw but no
// Gain in dB, and it ignores packet resend requests. Its timestamps are this
// host's wall clock in ns. Its frame ids start at 65401 and wrap after 65535
// to 1, as 16-bit GigE Vision ids do. Each camera needs an address of its own
// (see gige_address.h).
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>

#include <opencv2/core.hpp>

#include "capture/gige_address.h"

namespace ws {

struct FakeGigeCameraConfig {
  std::string address = "127.0.0.1";  // an IPv4 address of this host
  std::string serial = "FAKE";        // at most 15 characters
  cv::Size size{1280, 960};           // what the camera starts with (Width x Height)
  std::string pixel_format = "Mono8";
  // How often the camera looks for a software trigger: the trigger's latency.
  double trigger_poll_hz = 1000;
  // How long to wait for another process's fake camera to free the address.
  std::chrono::milliseconds address_wait{30000};
  GvcpPortClaim::Waiting waiting;  // told once when it has to wait for the address
};

class FakeGigeCamera {
 public:
  // A frame the camera is about to send.
  struct FrameRequest {
    int64_t timestamp_ns;  // its exposure: this host's wall clock, also its camera timestamp
    // The first frame since a client started acquiring. Aravis's simulator
    // polls slowly until it has sent one, so this one comes up to 100 ms late.
    bool first_of_stream;
  };
  // The image of a frame. Called from the camera's thread; whatever it returns
  // is converted to the format and size the client set. An empty Mat, or an
  // exception, gives a black frame.
  using FrameSource = std::function<cv::Mat(const FrameRequest& request)>;

  // Starts serving. Throws CameraError when the address is not this host's,
  // is taken, or the configuration is bad.
  FakeGigeCamera(FakeGigeCameraConfig config, FrameSource source);
  ~FakeGigeCamera();
  FakeGigeCamera(const FakeGigeCamera&) = delete;
  FakeGigeCamera& operator=(const FakeGigeCamera&) = delete;

  // The camera leaves the network (as unplugged): it answers nothing any more.
  void Stop();
  // It comes back as after a power cycle: registers reset to the config, no
  // controller, not acquiring. Throws CameraError like the constructor.
  void Start();
  bool running() const;

  std::string device_id() const { return "Aravis-Fake-" + config_.serial; }
  const FakeGigeCameraConfig& config() const { return config_; }
  uint64_t frames_served() const { return frames_served_; }
  // Why the last frame that could not be served was black, "" if none.
  std::string last_error() const;

 private:
  struct Server;  // the Aravis objects
  // Writes the source's frame (black on failure) into `bytes` bytes at `data`.
  void Fill(void* data, size_t bytes, int width, int height, uint32_t pixel_format,
            const FrameRequest& request);

  const FakeGigeCameraConfig config_;
  const FrameSource source_;
  GvcpPortClaim claim_;
  std::unique_ptr<Server> server_;
  std::atomic<uint64_t> frames_served_{0};
  mutable std::mutex error_mutex_;
  std::string last_error_;
};

}  // namespace ws
