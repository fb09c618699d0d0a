// stereo-health: watches the calibration's health on live (or logged) stereo
// pairs, the vertical disparity of matched features in the rectified pair,
// publishes CALIBRATION_HEALTH, and on `refine` repairs the extrinsics.
#include <cstdio>
#include <string>

#include "health/health_node.h"
#include "rectify/rectify_options.h"
#include "runtime/max_image_pixels_option.h"
#include "runtime/output_folder.h"
#include "runtime/process_cli.h"

int main(int argc, char** argv) {
  ws::ProcessCli cli("stereo-health",
                     "Rectifies a STEREO_IMAGES pair every --period seconds through the calibration "
                     "(--calib FILE.yaml, then every STEREO_CALIBRATION), matches sparse features and "
                     "measures their vertical disparity dy, and publishes CALIBRATION_HEALTH (median and "
                     "95th percentile |dy|, dy per image region, verdict ok / misaligned / unknown). On a "
                     "`refine` STEREO_COMMAND (or with --refine at the end of a log) it re-estimates R and "
                     "the direction of T from the matches and publishes the corrected STEREO_CALIBRATION.");
  ws::HealthConfig c;
  std::string calib_file;
  auto& app = cli.app();
  app.add_option("--calib", calib_file,
                 "Calibration file (stereo-calibrate --out) to start with; a STEREO_CALIBRATION replaces it")
      ->check(CLI::ExistingFile);
  ws::AddRectifyOptions(app, c.rectify);  // as stereo-match's
  ws::AddMaxImagePixelsOption(app, c.max_image_pixels);
  app.add_option("--period", c.period_s, "Seconds of message time between checked frames (0: every frame)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--max-dy", c.verdict.max_dy, "Median |dy| (px) above which a frame says misaligned")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--window", c.verdict.window, "Checked frames the verdict and figures look at")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  app.add_option("--confirm", c.verdict.confirm,
                 "Newest usable frames that must agree to change the verdict (at most --window)")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  app.add_option("--min-matches", c.verdict.min_matches, "Matches a frame needs to count (else unknown)")
      ->check(CLI::Range(5, 100000))
      ->capture_default_str();
  app.add_option("--min-regions", c.verdict.min_regions, "Grid regions a frame's matches must reach to count")
      ->check(CLI::Range(1, 10000))
      ->capture_default_str();
  app.add_option("--max-corners", c.features.max_corners, "Corners per image")
      ->check(CLI::Range(10, 100000))
      ->capture_default_str();
  app.add_option("--min-strength", c.features.min_strength,
                 "Weakest corner used: Shi-Tomasi's smaller eigenvalue (3 x 3, grey levels as 0..1; a corner "
                 "of 25 grey levels is about 2e-3, noise of 5 grey levels peaks at 1.3e-3)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--search-rows", c.features.search_rows, "Largest |dy| (px) of a match candidate")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--max-disparity", c.features.max_disparity, "Largest disparity (px) of a match candidate")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--ransac-px", c.features.ransac_px, "Largest |dy - field| (px) of a RANSAC inlier (the field: dy smooth over the image)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_flag("--refine", c.refine_at_end, "At the end of a file:// input, refine the extrinsics (see --out)");
  app.add_option("--out", c.out_yaml, "Where a refined calibration is written (calibration file format)");
  app.add_option("--report", c.report_json, "At the end of a file:// input, the figures as JSON");
  app.add_option("--min-refine-matches", c.refine.min_matches, "Matches a refinement needs")
      ->check(CLI::Range(10, 10000000))
      ->capture_default_str();
  app.add_option("--min-refine-regions", c.refine.min_regions,
                 "Grid regions with 10 or more matches a refinement needs")
      ->check(CLI::Range(1, 10000))
      ->capture_default_str();
  app.add_option("--max-correction-deg", c.refine.max_correction_deg,
                 "Largest correction of R (or of T's direction) applied; larger ones are refused")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--max-kept-matches", c.max_kept_matches, "Matches kept for refinement (newest frames)")
      ->check(CLI::Range(10, 10000000))
      ->capture_default_str();
  if (auto rc = cli.Parse(argc, argv)) return *rc;
  if (c.verdict.confirm > c.verdict.window) {
    std::fprintf(stderr, "stereo-health: --confirm (%d) must not exceed --window (%d)\n", c.verdict.confirm,
                 c.verdict.window);
    return 2;
  }

  try {
    ws::RequireWritableFolderOf("--out", c.out_yaml);
    ws::RequireWritableFolderOf("--report", c.report_json);
    ws::Process process(cli.options());
    ws::HealthNode node(process, c);
    node.Start(calib_file);
    return process.Run();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "stereo-health: %s\n", e.what());
    return 1;
  }
}
