// --max-image-pixels, the same for every process that decodes images or
// builds rectification maps (stereo-detect, stereo-match, stereo-health):
// larger images and calibrations are refused before any pixel is decoded or
// mapped (lcm_io/image_codec.h, kDefaultMaxImagePixels).
#pragma once

#include <cstdint>

#include <CLI/CLI.hpp>

namespace ws {

void AddMaxImagePixelsOption(CLI::App& app, int64_t& max_pixels);

}  // namespace ws
