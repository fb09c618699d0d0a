#include "fake_cameras/fake_gige_camera.h"

#include <arv.h>

#include <cstring>

#include "capture/camera_error.h"
#include "capture/gobject_ptr.h"
#include "capture/pixel_format.h"

namespace ws {
namespace {

constexpr size_t kMaxSerialLength = 15;  // GigE Vision bootstrap: 16 bytes with the NUL
// GigE Vision bootstrap register "Stream Channel Port 0": the client's UDP
// port for the stream, new for every stream a client opens.
constexpr guint32 kStreamChannelPort = 0x0D00;

FakeGigeCameraConfig Validated(FakeGigeCameraConfig config) {
  if (config.serial.empty() || config.serial.size() > kMaxSerialLength)
    throw CameraError("fake camera serial '" + config.serial + "' must have 1 to 15 characters");
  if (config.size.width <= 0 || config.size.height <= 0)
    throw CameraError("fake camera size must be positive");
  const uint32_t code = PixelFormatCode(config.pixel_format);
  if (code == ARV_PIXEL_FORMAT_BGR_8_PACKED)
    throw CameraError("the fake camera offers Mono8, Mono16 and RGB8, not BGR8");
  if (!(config.trigger_poll_hz > 0)) throw CameraError("trigger_poll_hz must be > 0");
  return config;
}

}  // namespace

// The Aravis simulator, from Start() to Stop().
struct FakeGigeCamera::Server {
  FakeGigeCamera* owner;
  GObjectPtr<ArvGvFakeCamera> camera;
  ArvFakeCamera* registers = nullptr;  // owned by camera
  guint32 stream_port = 0;             // of the latest frame sent

  // Aravis's fill-pattern callback, called from the simulator's thread.
  static void Fill(ArvBuffer* buffer, void* user_data, guint32 /*exposure_us*/, guint32 /*gain*/,
                   ArvPixelFormat format) {
    auto* server = static_cast<Server*>(user_data);
    guint32 port = 0;
    arv_fake_camera_read_register(server->registers, kStreamChannelPort, &port);
    const FrameRequest request{int64_t(arv_buffer_get_timestamp(buffer)),
                               port != server->stream_port};
    server->stream_port = port;
    size_t received = 0;  // what Aravis reports: nothing yet
    void* data = const_cast<void*>(arv_buffer_get_data(buffer, &received));
    const int width = arv_buffer_get_image_width(buffer);
    const int height = arv_buffer_get_image_height(buffer);
    const size_t bytes =
        size_t(width) * size_t(height) * ARV_PIXEL_FORMAT_BIT_PER_PIXEL(format) / 8;
    server->owner->Fill(data, bytes, width, height, format, request);
  }
};

FakeGigeCamera::FakeGigeCamera(FakeGigeCameraConfig config, FrameSource source)
    : config_(Validated(std::move(config))),
      source_(std::move(source)),
      claim_(config_.address, config_.address_wait, config_.waiting) {
  Start();
}

FakeGigeCamera::~FakeGigeCamera() { Stop(); }

void FakeGigeCamera::Start() {
  if (server_) return;
  claim_.CheckPortFree();
  auto server = std::make_unique<Server>();
  server->owner = this;
  server->camera.reset(arv_gv_fake_camera_new(config_.address.c_str(), config_.serial.c_str()));
  if (!server->camera || !arv_gv_fake_camera_is_running(server->camera.get()))
    throw CameraError("cannot serve a fake camera at " + config_.address);
  ArvFakeCamera* fake = arv_gv_fake_camera_get_fake_camera(server->camera.get());
  server->registers = fake;
  const guint32 width = guint32(config_.size.width);
  const guint32 height = guint32(config_.size.height);
  arv_fake_camera_write_register(fake, ARV_FAKE_CAMERA_REGISTER_SENSOR_WIDTH, width);
  arv_fake_camera_write_register(fake, ARV_FAKE_CAMERA_REGISTER_SENSOR_HEIGHT, height);
  arv_fake_camera_write_register(fake, ARV_FAKE_CAMERA_REGISTER_WIDTH, width);
  arv_fake_camera_write_register(fake, ARV_FAKE_CAMERA_REGISTER_HEIGHT, height);
  arv_fake_camera_write_register(fake, ARV_FAKE_CAMERA_REGISTER_PIXEL_FORMAT,
                                 PixelFormatCode(config_.pixel_format));
  arv_fake_camera_set_trigger_frequency(fake, config_.trigger_poll_hz);
  arv_fake_camera_set_fill_pattern(fake, Server::Fill, server.get());
  server_ = std::move(server);
}

void FakeGigeCamera::Stop() { server_.reset(); }

bool FakeGigeCamera::running() const { return server_ != nullptr; }

std::string FakeGigeCamera::last_error() const {
  std::lock_guard<std::mutex> lock(error_mutex_);
  return last_error_;
}

void FakeGigeCamera::Fill(void* data, size_t bytes, int width, int height, uint32_t pixel_format,
                          const FrameRequest& request) {
  try {
    MatToPixels(source_(request), pixel_format, width, height, data);
  } catch (const std::exception& e) {
    std::memset(data, 0, bytes);
    std::lock_guard<std::mutex> lock(error_mutex_);
    last_error_ = device_id() + ": cannot serve a frame: " + e.what();
  }
  ++frames_served_;
}

}  // namespace ws
