// stereo-view: the live page of the rig, in any browser: the calibration
// coach (both images with the corners found, the coverage, the uncertainty
// of the views so far, the list of views, after a solve the residual and
// uncertainty maps and the model table, the hint, the command buttons) and the depth view (the rectified pair, the disparity in metres,
// the filtered cloud in 3-D, the plane, the health, every process's rates).
#include <sys/resource.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>

#include "page_server.h"
#include "rig/rig_file.h"
#include "runtime/process.h"
#include "runtime/process_cli.h"
#include "view/view_node.h"

int main(int argc, char** argv) {
  ws::ProcessCli cli("stereo-view",
                     "Serves the rig's live page over HTTP (open http://ADDRESS:PORT/): the calibration "
                     "view (both images with the corners found, the coverage, the projection uncertainty of the "
                     "views so far, the list of views with a thumbnail and a remove button each, the residual and projection "
                     "uncertainty maps and the model table after a solve, the hint, buttons for solve, "
                     "save, reset and restore) and the depth view (the rectified pair, the disparity in "
                     "metres, the filtered cloud in 3-D, the plane, the health, the processes' rates). "
                     "Read-only without --key-file; with it the buttons send signed commands to "
                     "stereo-calibrate. A slow browser only misses updates (counted as skipped on "
                     "'browsers' in PROCESS_STATUS); the bus is never kept waiting.");
  auto& app = cli.app();
  int port = 8077;
  std::string address = "127.0.0.1", calib_file, three_dir = "/usr/share/javascript/three";
  ws::view::ViewOptions options;
  app.add_option("--port", port, "TCP port of the page (0: any free port, printed and logged)")->check(CLI::Range(0, 65535))->capture_default_str();
  app.add_option("--listen", address,
                 "Address to listen on: 127.0.0.1 (this host only), 0.0.0.0 (every network: anyone "
                 "who reaches the port sees the rig, and with the key can command it). The page is served "
                 "by the address a browser reached it on, or localhost, not by a host name (docs/security.md)")
      ->capture_default_str();
  app.add_option("--calib", calib_file,
                 "Calibration file the depth view rectifies with until a STEREO_CALIBRATION comes")
      ->check(CLI::ExistingFile);
  app.add_option("--image-hz", options.image_hz, "Images, disparities and clouds sent to the page per second, at most")
      ->check(CLI::Range(0.1, 30.0))
      ->capture_default_str();
  app.add_option("--max-width", options.max_width, "Pixels across of the images sent to the page, at most")
      ->check(CLI::Range(64, 4096))
      ->capture_default_str();
  app.add_option("--cloud-points", options.cloud_points, "Points of a cloud sent to the page, at most")
      ->check(CLI::Range(1, 1000000))
      ->capture_default_str();
  app.add_option("--first-view", options.first_view,
                 "The tab a page opens on until its user picks one: calibration, or depth (the run launch)")
      ->check(CLI::IsMember({"calibration", "depth"}))
      ->capture_default_str();
  app.add_option("--recording", options.recording,
                 "The launch's LCM log: the page shows its size and says when it reached --recording-cap-mb "
                 "(the launcher stops recording there); stereo-status says it too, as stereo-view's last error");
  app.add_option("--recording-cap-mb", options.recording_cap_mb, "The recording's cap (the launch's max_log_mb)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--recording-files", options.recording_files,
                 "1: one file, stopped at the cap; N > 1: a rolling recording (the launch's rolling_log), "
                 "LOG.0 the newest to LOG.N-1, the oldest deleted: the page and stereo-status say how many "
                 "minutes it holds")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  app.add_option("--three-dir", three_dir, "Folder of three.js (Debian's libjs-three)")->capture_default_str();
  int niceness = 10;
  app.add_option("--nice", niceness,
                 "Scheduling niceness (0 to 19): the page is for people, the depth chain steers the robot, so "
                 "stereo-view yields the CPU to it")
      ->check(CLI::Range(0, 19))
      ->capture_default_str();
  if (auto rc = cli.Parse(argc, argv)) return *rc;
  // Before any thread starts: Linux keeps niceness per thread, and new threads inherit it.
  if (setpriority(PRIO_PROCESS, 0, niceness) != 0)
    std::fprintf(stderr, "stereo-view: warning: cannot set niceness %d: %s\n", niceness, std::strerror(errno));

  try {
    ws::Process process(cli.options());
    ws::view::EventHub hub;
    ws::view::BlobStore blobs;
    ws::view::Audience audience;
    ws::view::ViewNode node(process, hub, blobs, audience, options);
    if (!calib_file.empty()) node.SetRig(ws::StereoRigFromFile(calib_file), "calibration file " + calib_file);
    ws::view::PageServer server(process, hub, blobs, audience, node, address, port, three_dir);
    if (!cli.options().quiet)
      std::printf("stereo-view: open http://%s:%d/\n", address == "0.0.0.0" ? "localhost" : address.c_str(), server.port()),
          std::fflush(stdout);
    node.Start();
    return process.Run();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "stereo-view: %s\n", e.what());
    return 1;
  }
}
