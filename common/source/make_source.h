// stereo-capture's --source: "aravis:LEFT_ID,RIGHT_ID", "dir:PATH" or "sim:CONFIG.yaml".
#pragma once

#include <memory>
#include <string>

#include "source/stereo_source.h"

namespace ws {

struct SourceOptions {
  bool loop = false;          // dir: and sim: start again at the end
  bool mono = false;          // dir: every image is a left image (a one-camera rig)
  std::string rig_config;     // aravis: camera settings (config/rig/*.yaml)
};

// Throws std::invalid_argument for an unknown kind or a malformed spec, and
// std::runtime_error when the source cannot be opened.
std::unique_ptr<StereoSource> MakeStereoSource(const std::string& spec, const SourceOptions& options);

}  // namespace ws
