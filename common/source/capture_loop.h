// stereo-capture's loop: every pair from a source becomes one STEREO_IMAGES
// message, with frame ids that count every pair that was due, so a pair the
// source could not deliver leaves a gap that receivers count as dropped.
#pragma once

#include <cstdint>

#include "lcm_io/image_codec.h"
#include "runtime/process.h"
#include "source/stereo_source.h"

namespace ws {

struct CaptureOptions {
  double rate_hz = 0;       // pairs per second for unpaced sources, live only; 0: as fast as possible
  int64_t count = 0;        // stop after this many pairs (0: until the source ends)
  Compression compression = Compression::none;
  int jpeg_quality = 95;
  // utime from the frame index (period 1/rate, or 0.1 s) instead of the wall
  // clock, for reproducible logs from files and the simulator.
  bool frame_clock = false;
};

// Runs until the source ends, `count` pairs were due, or the process stops.
void RunCapture(Process& process, StereoSource& source, const CaptureOptions& options);

}  // namespace ws
