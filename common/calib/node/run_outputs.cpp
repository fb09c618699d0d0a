#include "calib/node/run_outputs.h"

#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "rig/rig_file.h"
#include "runtime/escaped.h"

namespace ws::calib {
namespace {

namespace fs = std::filesystem;

// Whether the regular file `path` opens as a file WriteCalibrationFile
// wrote: its title in the first comment (at most 4 KB read).
bool IsCalibrationFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string head(4096, '\0');
  in.read(head.data(), std::streamsize(head.size()));
  head.resize(size_t(in.gcount()));
  return head.find(kCalibrationFileTitle) != std::string::npos;
}

// Whether `path` lies inside the folder `dir` (both as they resolve).
bool Inside(const std::string& path, const std::string& dir) {
  std::error_code error;
  const fs::path folder = fs::weakly_canonical(dir, error);
  if (error) return false;
  const fs::path file = fs::weakly_canonical(fs::absolute(path), error);
  if (error) return false;
  const auto [end, at] = std::mismatch(folder.begin(), folder.end(), file.begin(), file.end());
  return end == folder.end() && at != file.end();
}

void Check(const std::string& what, const std::string& path, bool calibration, bool folder,
           const std::string& images) {
  if (path.empty()) return;
  auto refuse = [&](const std::string& why) {
    throw std::invalid_argument(what + " " + Quoted(path) + " " + why);
  };
  if (!images.empty() && Inside(path, images))
    refuse("is inside the image folder " + Quoted(images) +
           ", where the next run would read it as an image: write it elsewhere");
  struct stat info;
  if (lstat(path.c_str(), &info) != 0) return;  // a new file
  if (S_ISLNK(info.st_mode)) refuse("is a symlink: an output never follows one (remove it or give another name)");
  if (folder) {
    if (!S_ISDIR(info.st_mode)) refuse("exists and is not a folder: give another name");
    return;
  }
  if (S_ISDIR(info.st_mode)) refuse("is a folder: give a file name, e.g. " + path + "/calib.yaml");
  if (!S_ISREG(info.st_mode)) refuse("exists and is not a regular file: give another name");
  if (calibration && !IsCalibrationFile(path))
    refuse("exists and is not a widestereo calibration: it is left untouched (give another name)");
}

}  // namespace

void RequireSafeOutputs(const RunOutputs& outputs, const std::string& images) {
  const std::string extension = fs::path(outputs.yaml).extension().string();
  if (!outputs.yaml.empty() && extension != ".yaml" && extension != ".yml")
    throw std::invalid_argument("--out " + Quoted(outputs.yaml) + ": a calibration file ends in .yaml (or .yml)");
  Check("--out", outputs.yaml, true, false, images);
  for (const std::string& model : outputs.model_yamls) Check("the model file", model, true, false, images);
  Check("--report", outputs.report, false, false, images);
  Check("the figures' folder", outputs.plots, false, true, images);
  Check("the corners' log", outputs.corners_log, false, false, images);
  Check("the messages' log", outputs.messages_log, false, false, images);
}

}  // namespace ws::calib
