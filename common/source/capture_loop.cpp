#include "source/capture_loop.h"

#include <chrono>
#include <thread>

#include "lcm_io/channels.h"
#include "lcm_io/lcm_log.h"
#include "runtime/wall_clock.h"
#include "widestereo/stereo_frame_t.hpp"

namespace ws {
namespace {

void MirrorSourceCounters(Process& process, const StereoSource& source) {
  for (const auto& [input, counts] : source.Counters()) {
    ChannelCounters& c = process.Counters(input);
    c.received = counts.received;
    c.dropped = counts.dropped;
    c.rejected = counts.rejected;
  }
}

}  // namespace

void RunCapture(Process& process, StereoSource& source, const CaptureOptions& options) {
  const bool live = LcmFileUrlPath(process.options().out_url).empty();
  const bool paced = live && options.rate_hz > 0 && !source.Paced();
  const int64_t period_us = int64_t(1e6 / (options.rate_hz > 0 ? options.rate_hz : 10.0));
  if (options.frame_clock) process.UseMessageClock();
  const auto start = std::chrono::steady_clock::now();
  ChannelCounters& images = process.Counters(channel::kStereoImages);
  process.SetProgress([&] { return "frame " + std::to_string(images.published.load()); });

  int64_t frame_id = 0;  // pairs due so far: published or lost
  while (!process.Stopping() && (options.count == 0 || frame_id < options.count)) {
    if (paced) std::this_thread::sleep_until(start + std::chrono::microseconds(frame_id * period_us));
    StageTimer read(process.stage_times(), "read");
    std::optional<StereoPair> pair = source.Next();
    read.Stop();
    MirrorSourceCounters(process, source);
    for (const std::string& event : source.TakeEvents()) process.log().Info(event);
    if (!pair) break;
    if (pair->nothing_due) {
      process.SetState(pair->label);
      process.Tick();
      continue;
    }
    process.SetState("capturing");
    const int64_t id = frame_id++;
    if (pair->left.empty() || (pair->right.empty() && !source.Mono())) {
      process.ReportRecurring("frame " + std::to_string(id) + " lost: " + pair->label);
      process.Tick();
      continue;
    }
    widestereo::stereo_frame_t frame{};
    frame.frame_id = id;
    frame.utime = pair->utime ? pair->utime
                  : options.frame_clock ? (id + 1) * period_us
                                        : WallMicros();
    process.ObserveTime(frame.utime);
    StageTimer encode(process.stage_times(), "encode");
    frame.left = MatToImage(pair->left, frame.utime, options.compression, options.jpeg_quality);
    frame.right = source.Mono() ? NoImage(frame.utime)
                                : MatToImage(pair->right, frame.utime, options.compression,
                                             options.jpeg_quality);
    encode.Stop();
    process.Publish(channel::kStereoImages, frame);
    process.log().Detail("frame " + std::to_string(id) + ": " + pair->label);
    process.Tick();
  }
}

}  // namespace ws
