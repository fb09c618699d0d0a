#include "runtime/max_image_pixels_option.h"

#include "lcm_io/image_codec.h"

namespace ws {

void AddMaxImagePixelsOption(CLI::App& app, int64_t& max_pixels) {
  max_pixels = kDefaultMaxImagePixels;
  app.add_option("--max-image-pixels", max_pixels,
                 "Largest image (width x height) decoded, and largest calibration image size "
                 "rectified; larger frames and calibrations are refused and counted as rejected")
      ->check(CLI::Range(int64_t(1), int64_t(1) << 28))
      ->capture_default_str();
}

}  // namespace ws
