#include "rectify/rectify_options.h"

namespace ws {

void AddRectifyOptions(CLI::App& app, RectifyOptions& options) {
  app.add_option("--focal-scale", options.focal_scale,
                 "Rectified focal length over the cameras' smallest (< 1 keeps more field)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
}

}  // namespace ws
