#include "capture/arv_session.h"

#include <algorithm>
#include <fstream>

#include <opencv2/core.hpp>

#include "capture/camera_error.h"
#include "capture/gige_address.h"
#include "capture/pixel_format.h"

namespace ws {
namespace {

// GigE Vision bootstrap register "Control Channel Privilege": bit 0
// exclusive access, bit 1 control access, both 0 when no one controls the camera.
constexpr guint64 kControlChannelPrivilege = 0x0A00;
constexpr guint32 kControlBits = 0x3;

// A frame arrives as a burst of UDP packets; the receive socket must hold
// several frames or packets overflow it (on loopback even one frame does).
constexpr size_t kSocketBufferFrames = 4;
constexpr size_t kMaxSocketBuffer = size_t(64) << 20;

// Applies a setting the camera may lack: a missing feature or a rejected value
// is a warning, not an error.
void ApplyOptional(const std::string& what, bool available,
                   const std::function<void(GError**)>& apply, std::vector<std::string>* warnings) {
  if (!available) {
    warnings->push_back("camera has no " + what + " feature; left as the camera has it");
    return;
  }
  GError* error = nullptr;
  apply(&error);
  if (error) warnings->push_back(what + " not applied: " + TakeError(&error));
}

std::string AvailablePixelFormats(ArvCamera* camera) {
  guint n = 0;
  const char** names = arv_camera_dup_available_pixel_formats_as_strings(camera, &n, nullptr);
  std::string list;
  for (guint i = 0; i < n; ++i) list += std::string(list.empty() ? "" : ", ") + names[i];
  g_free(names);
  return list;
}

// The kernel's cap on a socket's receive buffer, or 0 when unknown.
size_t ReceiveBufferCap() {
  std::ifstream file("/proc/sys/net/core/rmem_max");
  size_t bytes = 0;
  file >> bytes;
  return bytes;
}

std::string DeviceAddress(ArvCamera* camera) {
  GSocketAddress* socket_address =
      arv_gv_device_get_device_address(ARV_GV_DEVICE(arv_camera_get_device(camera)));
  if (!G_IS_INET_SOCKET_ADDRESS(socket_address)) return "";
  gchar* text = g_inet_address_to_string(
      g_inet_socket_address_get_address(G_INET_SOCKET_ADDRESS(socket_address)));
  std::string address = text;
  g_free(text);
  return address;
}

}  // namespace

ArvSession::ArvSession(const std::string& id, const ArvCameraSettings& settings, int n_buffers,
                       std::function<void()> on_control_lost, std::vector<std::string>* warnings)
    : id_(id), on_control_lost_(std::move(on_control_lost)) {
  GError* error = nullptr;
  camera_.reset(arv_camera_new(id.c_str(), &error));
  if (!camera_) throw CameraError(id + ": cannot open: " + TakeError(&error));
  control_lost_handler_ = g_signal_connect(arv_camera_get_device(camera_.get()), "control-lost",
                                           G_CALLBACK(OnControlLost), this);
  try {
    Configure(settings, warnings);
    CreateStream(n_buffers, warnings);
    arv_camera_start_acquisition(camera_.get(), &error);
    if (error) throw CameraError(id + ": cannot start acquisition: " + TakeError(&error));
  } catch (...) {
    MarkLost();  // nothing to stop
    Close();
    throw;
  }
  description_ = Describe();
}

ArvSession::~ArvSession() { Close(); }

void ArvSession::Close() {
  if (!camera_) return;
  if (!lost_) arv_camera_stop_acquisition(camera_.get(), nullptr);
  if (control_lost_handler_)
    g_signal_handler_disconnect(arv_camera_get_device(camera_.get()), control_lost_handler_);
  control_lost_handler_ = 0;
  stream_.reset();
  camera_.reset();  // ends the device's heartbeat thread, the only caller of OnControlLost
}

void ArvSession::OnControlLost(ArvDevice*, gpointer self) {
  auto* session = static_cast<ArvSession*>(self);
  session->control_lost_ = true;
  session->on_control_lost_();
}

void ArvSession::Configure(const ArvCameraSettings& settings, std::vector<std::string>* warnings) {
  ArvCamera* camera = camera_.get();
  GError* error = nullptr;
  if (arv_camera_is_gv_device(camera)) ConfigureGigE(settings, warnings);

  arv_camera_set_pixel_format_from_string(camera, settings.pixel_format.c_str(), &error);
  const bool format_set = !error && arv_camera_get_pixel_format(camera, &error) ==
                                        PixelFormatCode(settings.pixel_format);
  if (!format_set)
    throw CameraError(id_ + ": cannot use pixel format " + settings.pixel_format +
                      (error ? " (" + TakeError(&error) + ")" : "") + "; the camera offers " +
                      AvailablePixelFormats(camera));

  ApplyOptional(
      "exposure time", arv_camera_is_exposure_time_available(camera, nullptr),
      [&](GError** e) {
        if (arv_camera_is_exposure_auto_available(camera, nullptr))
          arv_camera_set_exposure_time_auto(camera, ARV_AUTO_OFF, e);
        if (!*e) arv_camera_set_exposure_time(camera, settings.exposure_us, e);
      },
      warnings);
  // Only "Gain" is in dB; "GainRaw" has camera-specific units.
  ApplyOptional(
      "Gain (dB)", arv_camera_is_feature_available(camera, "Gain", nullptr),
      [&](GError** e) {
        if (arv_camera_is_gain_auto_available(camera, nullptr))
          arv_camera_set_gain_auto(camera, ARV_AUTO_OFF, e);
        if (!*e) arv_camera_set_float(camera, "Gain", settings.gain_db, e);
      },
      warnings);

  if (settings.trigger == TriggerMode::software) {
    if (!arv_camera_is_software_trigger_supported(camera, nullptr))
      throw CameraError(id_ + ": the camera has no software trigger (use trigger: free-run)");
    arv_camera_set_trigger(camera, "Software", &error);
    if (error) throw CameraError(id_ + ": cannot set the software trigger: " + TakeError(&error));
  } else {
    arv_camera_clear_triggers(camera, &error);
    if (error) throw CameraError(id_ + ": cannot switch triggers off: " + TakeError(&error));
    ApplyOptional(
        "frame rate", arv_camera_is_frame_rate_available(camera, nullptr),
        [&](GError** e) { arv_camera_set_frame_rate(camera, settings.frame_rate_hz, e); },
        warnings);
  }
  arv_camera_set_acquisition_mode(camera, ARV_ACQUISITION_MODE_CONTINUOUS, &error);
  if (error) throw CameraError(id_ + ": cannot set continuous acquisition: " + TakeError(&error));
}

void ArvSession::ConfigureGigE(const ArvCameraSettings& settings,
                               std::vector<std::string>* warnings) {
  ArvCamera* camera = camera_.get();
  address_ = DeviceAddress(camera);
  // The packet socket (Aravis's fast path, when it has CAP_NET_RAW) also sees
  // a local camera's packets on their way out and mixes up the streams.
  const auto local = LocalIpv4Addresses();
  if (std::find(local.begin(), local.end(), address_) != local.end())
    arv_camera_gv_set_stream_options(camera, ARV_GV_STREAM_OPTION_PACKET_SOCKET_DISABLED);

  GError* error = nullptr;
  if (settings.packet_size > 0)
    arv_camera_gv_set_packet_size(camera, settings.packet_size, &error);
  else
    arv_camera_gv_auto_packet_size(camera, &error);
  if (error) warnings->push_back("packet size not applied: " + TakeError(&error));
}

void ArvSession::CreateStream(int n_buffers, std::vector<std::string>* warnings) {
  GError* error = nullptr;
  const guint payload = arv_camera_get_payload(camera_.get(), &error);
  if (error) throw CameraError(id_ + ": cannot read the payload size: " + TakeError(&error));
  stream_.reset(arv_camera_create_stream(camera_.get(), nullptr, nullptr, &error));
  if (!stream_) throw CameraError(id_ + ": cannot open a stream: " + TakeError(&error));
  if (ARV_IS_GV_STREAM(stream_.get())) {
    const size_t wanted = std::min(kSocketBufferFrames * payload, kMaxSocketBuffer);
    g_object_set(stream_.get(), "socket-buffer", ARV_GV_STREAM_SOCKET_BUFFER_FIXED,
                 "socket-buffer-size", gint(wanted), nullptr);
    const size_t cap = ReceiveBufferCap();
    if (cap != 0 && cap < 2 * size_t(payload))
      warnings->push_back(cv::format(
          "net.core.rmem_max is %zu bytes, less than two frames (%zu bytes): expect incomplete "
          "frames; raise it, e.g. 'sysctl -w net.core.rmem_max=%zu'",
          cap, 2 * size_t(payload), wanted));
  }
  for (int i = 0; i < n_buffers; ++i)
    arv_stream_push_buffer(stream_.get(), arv_buffer_new_allocate(payload));
}

std::string ArvSession::Describe() const {
  ArvCamera* camera = camera_.get();
  gint x = 0, y = 0, width = 0, height = 0;
  arv_camera_get_region(camera, &x, &y, &width, &height, nullptr);
  const char* vendor = arv_camera_get_vendor_name(camera, nullptr);
  const char* model = arv_camera_get_model_name(camera, nullptr);
  const char* serial = arv_camera_get_device_serial_number(camera, nullptr);
  std::string text = id_ + ": " + (vendor ? vendor : "?") + " " + (model ? model : "?") +
                     " (serial " + (serial ? serial : "?") + ")";
  if (!address_.empty()) text += " at " + address_;
  text += cv::format(", %dx%d %s", width, height,
                     PixelFormatName(arv_camera_get_pixel_format(camera, nullptr)).c_str());
  if (arv_camera_is_gv_device(camera))
    text += cv::format(", packets of %u bytes", arv_camera_gv_get_packet_size(camera, nullptr));
  return text;
}

std::string ArvSession::SoftwareTrigger() {
  GError* error = nullptr;
  arv_camera_software_trigger(camera_.get(), &error);
  return TakeError(&error);
}

std::string ArvSession::CheckInControl() {
  GError* error = nullptr;
  if (!arv_camera_is_gv_device(camera_.get())) {
    arv_camera_get_payload(camera_.get(), &error);
    return TakeError(&error);
  }
  guint32 privilege = 0;
  if (!arv_device_read_register(arv_camera_get_device(camera_.get()), kControlChannelPrivilege,
                                &privilege, &error))
    return "no answer: " + TakeError(&error);
  if ((privilege & kControlBits) == 0) return "the camera restarted: it has no controller";
  return "";
}

ArvBuffer* ArvSession::Pop(std::chrono::microseconds timeout) {
  if (timeout.count() <= 0) return arv_stream_try_pop_buffer(stream_.get());
  return arv_stream_timeout_pop_buffer(stream_.get(), guint64(timeout.count()));
}

}  // namespace ws
