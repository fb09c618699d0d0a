// The path of a process replaying a file:// log (runtime/process.cpp): the
// scan of the log's structure (lcm_io/lcm_log.h), then LCM's own file
// provider delivering the events (from a copy of the complete ones where LCM
// would not stop exactly at the damage), each decoded as the type of its
// channel. LCM must read exactly the complete events the scan counted and
// deliver every one on a channel a process reads. (Events on channels that
// are not ASCII are never delivered: glibc's regex '.' does not match those
// bytes in the C locale; no process reads such a channel.)
// Then the recovery of every intact event (RecoverLcmLog, what stereo-calibrate
// does with a damaged views file): every byte is in an event or counted
// lost, and what it recovers is an intact log of the same events.
#include <fstream>
#include <map>
#include <string>

#include <lcm/lcm-cpp.hpp>

#include "fuzz_support.h"
#include "lcm_io/channels.h"
#include "lcm_io/lcm_log.h"

namespace {

using Decoder = bool (*)(const void* data, int size);

template <class Msg>
bool DecodeAs(const void* data, int size) {
  try {
    ws::DecodeMessage<Msg>(data, size);
    return true;
  } catch (const ws::DecodeError&) {
    return false;
  }
}

const std::map<std::string, Decoder>& Decoders() {
  namespace ch = ws::channel;
  using namespace widestereo;
  static const std::map<std::string, Decoder> decoders = {
      {ch::kStereoImages, DecodeAs<stereo_frame_t>},
      {ch::kStereoCorners, DecodeAs<stereo_corners_t>},
      {ch::kStereoCommand, DecodeAs<command_t>},
      {ch::kCalibrationStatus, DecodeAs<calibration_status_t>},
      {ch::kCalibrationHealth, DecodeAs<calibration_health_t>},
      {ch::kStereoCalibration, DecodeAs<stereo_calibration_t>},
      {ch::kCalibrationResult, DecodeAs<calibration_result_t>},
      {ch::kCalibrationViews, DecodeAs<calibration_views_t>},
      {ch::kCalibrationPreview, DecodeAs<calibration_result_t>},
      {ch::kStereoDisparity, DecodeAs<disparity_t>},
      {ch::kStereoCloud, DecodeAs<point_cloud_t>},
      {ch::kStereoCloudFiltered, DecodeAs<point_cloud_t>},
      {ch::kCloudStats, DecodeAs<cloud_stats_t>},
      {ch::kProcessStatus, DecodeAs<process_status_t>},
  };
  return decoders;
}

bool DecodesAsItsChannel(const std::string& channel, const uint8_t* data, size_t size) {
  const auto decoder = Decoders().find(channel);
  return decoder != Decoders().end() && decoder->second(data, int(size));
}

void CheckRecovery(const std::string& path, int64_t size) {
  const ws::LcmLogRecovery recovery = ws::RecoverLcmLog(path, DecodesAsItsChannel);
  const std::string recovered = ws::EncodeLcmLog(recovery.events);
  if (recovery.file_bytes != size || int64_t(recovered.size()) + recovery.lost_bytes != size ||
      recovery.intact() != recovery.first_damage.empty() || recovery.lost_events < 0)
    ws::fuzz::Violated("inconsistent recovery: " + std::to_string(recovery.events.size()) + " events in " +
                       std::to_string(recovered.size()) + " bytes, " + std::to_string(recovery.lost_bytes) +
                       " lost of " + std::to_string(size) + ", damage '" + recovery.first_damage + "'");
  const std::string copy = path + ".recovered";
  if (!(std::ofstream(copy, std::ios::binary) << recovered)) ws::fuzz::Violated("cannot write " + copy);
  const ws::LcmLogRecovery again = ws::RecoverLcmLog(copy, DecodesAsItsChannel);
  if (!again.intact() || again.events.size() != recovery.events.size() ||
      ws::EncodeLcmLog(again.events) != recovered)
    ws::fuzz::Violated("the recovered events are not an intact log: " + again.first_damage);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = ws::fuzz::WriteInputFile(data, size, ".lcmlog");
  const ws::LcmLogScan scan = ws::ScanLcmLog(path);
  if (scan.file_bytes != int64_t(size) || scan.valid_bytes > scan.file_bytes ||
      scan.complete() != (scan.valid_bytes == scan.file_bytes))
    ws::fuzz::Violated("inconsistent scan: " + std::to_string(scan.valid_bytes) + " valid of " +
                       std::to_string(scan.file_bytes) + " bytes, problem '" + scan.problem + "'");
  CheckRecovery(path, int64_t(size));
  if (scan.events == 0) return 0;  // a process does not open an empty log

  std::string replayed = path;
  if (!scan.lcm_replays_exactly) {
    replayed = path + ".complete";
    ws::CopyCompleteEvents(path, scan, replayed);
  }
  // LCM's reader takes exactly the complete events from the file...
  int64_t read = 0, ours = 0;
  {
    lcm::LogFile log(replayed, "r");
    while (const lcm::LogEvent* event = log.readNextEvent()) {
      ++read;
      ours += Decoders().count(event->channel);
    }
  }
  if (read != scan.events)
    ws::fuzz::Violated("LCM's log reader read " + std::to_string(read) + " events, the scan found " +
                       std::to_string(scan.events) + " complete ones");
  // ... and the file provider hands every one on a process's channel to its subscriber.
  lcm::LCM lcm("file://" + replayed + "?speed=0");
  if (!lcm.good()) ws::fuzz::Violated("LCM cannot open a log the scan read");
  int64_t delivered = 0;
  for (const auto& [channel, decoder] : Decoders())
    lcm.subscribeFunction(
        channel,
        +[](const lcm::ReceiveBuffer* rbuf, const std::string& ch, int64_t* count) {
          ++*count;
          Decoders().at(ch)(rbuf->data, int(rbuf->data_size));
        },
        &delivered);
  while (lcm.handle() == 0) {
  }
  if (delivered != ours)
    ws::fuzz::Violated("LCM delivered " + std::to_string(delivered) + " events on our channels, the log has " +
                       std::to_string(ours));
  return 0;
}
