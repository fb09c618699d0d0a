#include "runtime/max_image_pixels_option.h"

#include "lcm_io/image_codec.h"

namespace ws {

void AddMaxImagePixelsOption(CLI::App& app, int64_t& max_pixels) {
  max_pixels = kDefaultMaxImagePixels;
  app.add_option("--max-image-pixels", max_pixels,
                 "Largest image (width x height pixels) a frame or a calibration may have: larger "
                 "ones are refused, counted as rejected, before any pixel is decoded or mapped")
      ->check(CLI::Range(int64_t(1), int64_t(1) << 28))
      ->capture_default_str();
}

}  // namespace ws
