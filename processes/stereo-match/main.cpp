// stereo-match: rectifies every stereo pair through the calibrated lens model,
// matches it, and publishes the disparity and the point cloud.
#include <cstdio>
#include <string>

#include "lcm_io/channels.h"
#include "match/match_node.h"
#include "rectify/rectify_options.h"
#include "rig/rig_file.h"
#include "runtime/max_image_pixels_option.h"
#include "runtime/process_cli.h"

int main(int argc, char** argv) {
  ws::ProcessCli cli("stereo-match",
                     "Rectifies STEREO_IMAGES through the calibrated lens model (from --calib "
                     "FILE.yaml, then from every STEREO_CALIBRATION), matches them (block matching or SGBM), and publishes "
                     "STEREO_DISPARITY and STEREO_CLOUD (points in the left rectified frame). "
                     "Live, it matches the newest pair waiting and builds its cloud while the messages of the one "
                     "before are sent, and skips the pairs that come while the first maps for their image size are "
                     "built (they would be stale once they are), and, when stereo-cloud would still be filtering "
                     "one of its clouds with another waiting by the time the pair's cloud came (its "
                     "CLOUD_STATS acknowledge them), skips the pair before matching it rather than have "
                     "stereo-cloud skip its cloud; with --latency-budget, it skips a pair whose cloud "
                     "would come later than the budget; the pairs it skips are "
                     "counted in PROCESS_STATUS, and with their reasons in its log. With "
                     "--save-rectified it writes the rectified pairs as PNG files to inspect, with "
                     "--save-disparity the disparity in colour with a legend in metres.");
  ws::MatchConfig config;
  std::string calib_file;
  auto& m = config.matcher;
  auto& app = cli.app();
  app.add_option("--calib", calib_file,
                 "Calibration file (stereo-calibrate --out) to start with; a STEREO_CALIBRATION "
                 "message replaces it")
      ->check(CLI::ExistingFile);
  m.kind = "sgbm3way";  // fast by default; sgbm on request
  app.add_option("--matcher", m.kind,
                 "sgbm3way (semi-global, parallel: every core), bm (block matching) or sgbm "
                 "(semi-global, 8 paths: the most accurate, the slowest)")
      ->check(CLI::IsMember({"sgbm3way", "bm", "sgbm"}))
      ->capture_default_str();
  app.add_option("--downscale", m.downscale,
                 "Rectify and match at 1/N resolution (N^2 less work): STEREO_DISPARITY (its f, cx, cy "
                 "and Q too), the cloud's pixels and --save-rectified are on that grid")
      ->check(CLI::Range(1, 8))
      ->capture_default_str();
  app.add_option("--num-disparities", m.num_disparities, "Disparity search range (multiple of 16)")->capture_default_str();
  app.add_option("--min-disparity", m.min_disparity, "Smallest disparity searched")->capture_default_str();
  app.add_option("--block-size", m.block_size, "Matching window (odd; the paper used 33 with bm)")->capture_default_str();
  app.add_option("--uniqueness", m.uniqueness_ratio, "Uniqueness ratio, percent")->capture_default_str();
  app.add_option("--speckle-window", m.speckle_window, "Speckle filter window (0: off)")->capture_default_str();
  app.add_option("--speckle-range", m.speckle_range, "Speckle filter disparity range")->capture_default_str();
  bool whole_image = false;
  app.add_flag("--whole-image", whole_image,
               "Match the whole rectified image, not only the box where both rectified images hold "
               "image (the common field) grown by the matcher's reach (for comparisons)");
  app.add_option("--latency-budget", config.latency_budget_ms,
                 "Live, milliseconds from a pair's capture stamp (this host's clock) to stereo-cloud's "
                 "CLOUD_STATS of its cloud: a pair whose age plus the median time of that rest would exceed it "
                 "is skipped before it is matched, while one of the last pairs was young enough to make it, so "
                 "that a chain that cannot keep up drops pairs early instead of delivering each one later "
                 "(0: no bound)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  ws::AddRectifyOptions(app, config.rectify);
  ws::AddMaxImagePixelsOption(app, config.max_image_pixels);
  std::string rectification = "auto";
  app.add_option("--rectification", rectification,
                 "pinhole, latlon (rows are epipolar planes, columns angles: fields to 180 degrees "
                 "and beyond) or auto (pinhole up to a 130-degree common field, else latlon)")
      ->check(CLI::IsMember({"pinhole", "latlon", "auto"}))
      ->capture_default_str();
  app.add_option("--max-depth", config.cloud.max_depth, "Farthest point put in the cloud, metres")->capture_default_str();
  config.cloud.step = 2;  // a full 1280x960 cloud is 13 MB a frame: full only on request
  app.add_option("--cloud-step", config.cloud.step,
                 "Every N-th pixel of every N-th row becomes a cloud point, N in full-resolution pixels: "
                 "the same image positions at any --downscale, their disparity interpolated on the "
                 "matched grid (N at least the downscale; 1: the full cloud; 2 makes the message 4x "
                 "smaller)")
      ->check(CLI::Range(1, 64))
      ->capture_default_str();
  auto* save_dir = app.add_option("--save-rectified", config.save_rectified.dir,
                                  "Folder for the rectified pairs as PNG, left_NNNNNN.png and "
                                  "right_NNNNNN.png (NNNNNN: the frame id, 6 digits; created if needed)");
  auto* disparity_dir = app.add_option("--save-disparity", config.save_disparity.dir,
                                       "Folder for the disparity as a colour PNG with its legend in metres, "
                                       "disparity_NNNNNN.png (created if needed)");
  int save_every = 1;
  auto* every = app.add_option("--save-every", save_every,
                               "With --save-rectified or --save-disparity: write the frames whose frame id is a "
                               "multiple of N")
                    ->check(CLI::PositiveNumber)
                    ->capture_default_str();
  if (auto rc = cli.Parse(argc, argv)) return *rc;
  if (every->count() && !save_dir->count() && !disparity_dir->count()) {
    std::fprintf(stderr, "stereo-match: --save-every requires --save-rectified or --save-disparity\n");
    return 2;
  }
  config.save_rectified.save_every = config.save_disparity.save_every = save_every;
  config.rectify.mode = ws::ParseRectificationMode(rectification);
  m.common_field_only = !whole_image;

  try {
    ws::Process process(cli.options());
    ws::MatchNode node(process, config);
    if (!calib_file.empty()) node.SetRig(ws::StereoRigFromFile(calib_file), "calibration file " + calib_file);
    process.Subscribe<widestereo::stereo_calibration_t>(
        ws::channel::kStereoCalibration, [&](const auto& msg) { node.OnCalibration(msg); });
    process.Subscribe<widestereo::stereo_frame_t>(
        ws::channel::kStereoImages, [&](auto& msg) { node.OnFrame(msg); }, 2);
    process.Subscribe<widestereo::cloud_stats_t>(  // the clouds of the pairs matched: gaps by design
        ws::channel::kCloudStats, [&](const auto& msg) { node.OnCloudStats(msg); }, 0,
        ws::Process::FrameGaps::ignore);
    return process.Run();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "stereo-match: %s\n", e.what());
    return 1;
  }
}
