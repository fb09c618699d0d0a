// stereo-fake-cameras: a simulated stereo rig served as two real GigE Vision
// cameras on this host (Aravis's camera simulator), for
// stereo-capture --source aravis:Aravis-Fake-LEFT,Aravis-Fake-RIGHT.
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "fake_cameras/fake_stereo_cameras.h"
#include "capture/gige_address.h"
#include "runtime/process.h"
#include "runtime/process_cli.h"

namespace {

const cv::Size kPatternSize{1280, 960};

// "WIDTHxHEIGHT", or an empty size for "".
cv::Size ParseSize(const std::string& text) {
  int width = 0;
  int height = 0;
  char x = 0;
  char extra = 0;
  if (text.empty()) return {};
  if (std::sscanf(text.c_str(), "%d%c%d%c", &width, &x, &height, &extra) != 3 || x != 'x' ||
      width <= 0 || height <= 0)
    throw std::invalid_argument("--size must be WIDTHxHEIGHT, got '" + text + "'");
  return {width, height};
}

// "auto" addresses become this host's first IPv4 addresses (gige_address.h)
// where no other camera serves; when too few are free, the next ones, whose
// camera then says what it waits for.
void ResolveAddresses(ws::FakeStereoCamerasConfig* config) {
  const std::vector<std::string> local = ws::LocalIpv4Addresses();
  std::vector<std::string> unused;
  for (const std::string& address : local)
    if (address != config->left_address && address != config->right_address)
      unused.push_back(address);
  std::stable_partition(unused.begin(), unused.end(), ws::GvcpAddressFree);
  for (std::string* address : {&config->left_address, &config->right_address}) {
    if (*address != "auto") continue;
    if (unused.empty())
      throw std::runtime_error(
          "two fake cameras need two IPv4 addresses of this host, one each; add one, e.g. "
          "'ip addr add 127.0.0.2/8 dev lo', or give --left-address and --right-address");
    *address = unused.front();
    unused.erase(unused.begin());
  }
}

}  // namespace

int main(int argc, char** argv) {
  ws::ProcessCli cli("stereo-fake-cameras",
                     "Serves two fake GigE Vision cameras on this host, whose frames come from "
                     "a moving test pattern, an image pair, a directory of left*/right* "
                     "images or the built-in simulator; stereo-capture reads them with the --source it prints.");
  ws::FakeStereoCamerasConfig config;
  config.left_address = config.right_address = "auto";
  std::string frames = "pattern";
  std::string size;
  double duration_s = 0;
  CLI::App& app = cli.app();
  app.add_option("--frames", frames,
                 "pattern | pair:LEFT_IMAGE,RIGHT_IMAGE | dir:PATH (left*/right* pairs) | "
                 "sim:CONFIG.yaml (the simulator's frames, over and over; writes its ground truth)")
      ->capture_default_str();
  app.add_option("--size", size,
                 "WIDTHxHEIGHT the cameras start with (default: the images' size, 1280x960 "
                 "for the pattern); other sizes are resized");
  app.add_option("--pixel-format", config.pixel_format, "Mono8 | Mono16 | RGB8")
      ->capture_default_str();
  app.add_option("--left-address", config.left_address,
                 "IPv4 address of this host for the left camera; auto: the first free one "
                 "(127.0.0.1 first)")
      ->capture_default_str();
  app.add_option("--right-address", config.right_address,
                 "the same for the right camera, which needs another address (e.g. "
                 "'ip addr add 127.0.0.2/8 dev lo')")
      ->capture_default_str();
  app.add_option("--left-serial", config.left_serial, "found as Aravis-Fake-SERIAL")
      ->capture_default_str();
  app.add_option("--right-serial", config.right_serial)->capture_default_str();
  app.add_option("--same-moment-ms", config.same_moment_ms,
                 "frames the two cameras expose this close show one simulated moment: give "
                 "the capture's pairing_tolerance_ms (and pairing_clock: camera)")
      ->capture_default_str();
  app.add_option("--duration", duration_s, "Exit after this many seconds (0: run until Ctrl-C)");
  if (auto rc = cli.Parse(argc, argv)) return *rc;

  try {
    ws::Process process(cli.options());
    config.size = ParseSize(size);
    config.waiting = [&process](const std::string& what) { process.log().Info(what); };
    ResolveAddresses(&config);
    const cv::Size pattern_size = config.size.empty() ? kPatternSize : config.size;
    ws::FakeStereoCameras cameras(config, ws::MakeFrameProvider(frames, pattern_size));
    process.log().Info("serving " + frames + " from " + config.left_address + " and " +
                       config.right_address +
                       "; read them with stereo-capture --source aravis:" + cameras.camera_ids());
    process.SetState("serving");
    auto& left = cameras.camera(ws::Side::left);
    auto& right = cameras.camera(ws::Side::right);
    process.SetProgress([&] {
      return "served " + std::to_string(left.frames_served()) + " left, " +
             std::to_string(right.frames_served()) + " right frames";
    });
    std::string reported;
    const int64_t start = process.Now();
    process.Every(1000000, [&] {
      for (const auto* camera : {&left, &right}) {
        const std::string error = camera->last_error();
        if (!error.empty() && error != reported) process.ReportError(reported = error);
      }
      if (duration_s > 0 && process.Now() - start >= duration_s * 1e6) process.Stop();
    });
    return process.Run();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "stereo-fake-cameras: %s\n", e.what());
    return 1;
  }
}
