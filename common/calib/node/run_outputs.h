// The files a stereo-calibrate run writes, and the checks that keep them
// from destroying anything, made before any work (docs/security.md,
// "Output files").
#pragma once

#include <string>
#include <vector>

namespace ws::calib {

// What a run writes: --out and, with several models, FILE.MODEL.yaml each;
// --report; the figures' folder; with --images the corners' log; a batch
// run's messages log. "" for what it does not write.
struct RunOutputs {
  std::string yaml;
  std::vector<std::string> model_yamls;
  std::string report, plots, corners_log, messages_log;
};

// Throws std::invalid_argument naming the output and what to do where one
//   - is a folder (the figures' folder: is not one), or --out does not end
//     in .yaml or .yml;
//   - is a symlink: an output never follows one;
//   - exists and is not a widestereo calibration (--out, the model files)
//     or not a regular file (the report, the logs);
//   - lies inside `images`, the folder --images reads ("" for none): the
//     next run would read it as an image.
void RequireSafeOutputs(const RunOutputs& outputs, const std::string& images);

}  // namespace ws::calib
