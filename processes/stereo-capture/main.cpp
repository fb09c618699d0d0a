// stereo-capture: publishes one STEREO_IMAGES message per stereo pair, from
// two GenICam cameras (Aravis), an image directory, or the built-in simulator.
#include <cstdio>

#include "runtime/process.h"
#include "runtime/process_cli.h"
#include "source/capture_loop.h"
#include "source/make_source.h"

int main(int argc, char** argv) {
  ws::ProcessCli cli("stereo-capture",
                     "Publishes stereo pairs on STEREO_IMAGES from two GenICam cameras (Aravis), "
                     "a directory of left*/right* images, or the built-in simulator.");
  std::string source_spec;
  std::string compression = "none";
  ws::SourceOptions source_options;
  ws::CaptureOptions capture;
  auto& app = cli.app();
  app.add_option("--source", source_spec, "aravis:LEFT_ID,RIGHT_ID | dir:PATH | sim:CONFIG.yaml")
      ->required();
  app.add_option("--rate", capture.rate_hz, "Pairs per second from dir: and sim: (0: as fast as possible)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--count", capture.count, "Stop after N pairs (0: when the source ends)")
      ->check(CLI::NonNegativeNumber);
  app.add_flag("--loop", source_options.loop, "dir: and sim: start again after the last pair");
  app.add_flag("--mono", source_options.mono,
               "A one-camera rig: every image of the dir: folder, in name order, is sent as the "
               "left image of a frame with no right image");
  app.add_option("--rig", source_options.rig_config, "Camera settings for aravis: (config/rig/*.yaml)");
  app.add_option("--compression", compression, "none, jpeg or png")
      ->check(CLI::IsMember({"none", "jpeg", "png"}));
  app.add_option("--jpeg-quality", capture.jpeg_quality, "JPEG quality")->check(CLI::Range(1, 100));
  app.add_flag("--frame-clock", capture.frame_clock,
               "Stamp pairs from their index and --rate instead of the wall clock "
               "(reproducible logs from dir: and sim:)");
  if (auto rc = cli.Parse(argc, argv)) return *rc;

  try {
    capture.compression = ws::ParseCompression(compression);
    ws::Process process(cli.options());
    auto source = ws::MakeStereoSource(source_spec, source_options);
    ws::RunCapture(process, *source, capture);
    return process.Finish();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "stereo-capture: %s\n", e.what());
    return 1;
  }
}
