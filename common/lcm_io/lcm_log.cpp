#include "lcm_io/lcm_log.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <memory>
#include <stdexcept>
#include <vector>

#include "lcm_io/big_endian.h"

namespace ws {
namespace {

constexpr uint32_t kSyncWord = 0xEDA1DA01;  // LCM's event log sync word
constexpr int64_t kHeaderBytes = 4 + 8 + 8 + 4 + 4;
constexpr int64_t kMaxChannelBytes = 256;
constexpr int64_t kLcmMaxChannelBytes = 1000;  // LCM's eventlog.c refuses this and more

// Why the bytes of `log` at `at` are not an intact event (nullptr when they
// are one: then *event holds it and *event_bytes its size).
const char* NotAnIntactEvent(const std::string& log, int64_t at, const LcmEventCheck& check,
                             LcmLogEvent* event, int64_t* event_bytes) {
  const int64_t left = int64_t(log.size()) - at;
  const auto* header = reinterpret_cast<const unsigned char*>(log.data()) + at;
  if (left >= 4 && BigEndian(header, 4) != kSyncWord) return "bad sync word";
  if (left < kHeaderBytes) return "truncated event header";
  const int64_t channel_bytes = int32_t(BigEndian(header + 20, 4));
  const int64_t data_bytes = int32_t(BigEndian(header + 24, 4));
  if (channel_bytes <= 0 || channel_bytes > kMaxChannelBytes || data_bytes < 0) return "impossible lengths";
  if (kHeaderBytes + channel_bytes + data_bytes > left) return "event cut off";
  const char* channel = log.data() + at + kHeaderBytes;
  if (!std::all_of(channel, channel + channel_bytes, [](char c) { return c > ' ' && c < 127; }))
    return "unprintable channel";
  const std::string name(channel, size_t(channel_bytes));
  const auto* data = header + kHeaderBytes + channel_bytes;
  if (!check(name, data, size_t(data_bytes))) return "data that does not decode";
  event->eventnum = int64_t(BigEndian(header + 4, 8));
  event->timestamp = int64_t(BigEndian(header + 12, 8));
  event->channel = name;
  event->data.assign(data, data + data_bytes);
  *event_bytes = kHeaderBytes + channel_bytes + data_bytes;
  return nullptr;
}

// The events lost in a damaged stretch of `bytes` between intact events
// numbered `before` and `after`: the gap in the numbers when it fits in the
// stretch, else (numbers not LCM's 0, 1, 2, ... or damaged) one.
int64_t LostBetween(int64_t before, int64_t after, int64_t bytes) {
  const int64_t most = bytes / (kHeaderBytes + 1);
  const uint64_t gap = uint64_t(after) - uint64_t(before) - 1;  // no overflow: unsigned
  return after > before && gap <= uint64_t(most) ? int64_t(gap) : 1;
}

}  // namespace

LcmLogScan ScanLcmLog(const std::string& path) {
  std::unique_ptr<FILE, int (*)(FILE*)> f(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!f) throw std::runtime_error("cannot open LCM log " + path);
  LcmLogScan scan;
  std::fseek(f.get(), 0, SEEK_END);
  scan.file_bytes = std::ftell(f.get());
  std::fseek(f.get(), 0, SEEK_SET);
  while (scan.valid_bytes < scan.file_bytes) {
    const int64_t left = scan.file_bytes - scan.valid_bytes;
    unsigned char header[kHeaderBytes];
    const int64_t header_bytes = std::min(left, kHeaderBytes);
    if (std::fread(header, 1, size_t(header_bytes), f.get()) != size_t(header_bytes)) {
      scan.problem = "unreadable event header";
      break;
    }
    if (header_bytes >= 4 && BigEndian(header, 4) != kSyncWord) {
      scan.problem = "bad sync word";
      scan.lcm_replays_exactly = false;
      break;
    }
    if (header_bytes < kHeaderBytes) {
      scan.problem = "truncated event header";
      break;
    }
    const int64_t channel_bytes = int64_t(BigEndian(header + 20, 4));
    const int64_t data_bytes = int64_t(BigEndian(header + 24, 4));
    if (channel_bytes <= 0 || channel_bytes > kMaxChannelBytes) {
      scan.problem = "bad channel length " + std::to_string(channel_bytes);
      scan.lcm_replays_exactly = channel_bytes <= 0 || channel_bytes >= kLcmMaxChannelBytes;
      break;
    }
    const int64_t event_bytes = kHeaderBytes + channel_bytes + data_bytes;
    if (event_bytes > left) {
      scan.problem = "event " + std::to_string(scan.events) + " is cut off (needs " +
                     std::to_string(event_bytes) + " bytes, " + std::to_string(left) + " left)";
      break;
    }
    std::fseek(f.get(), long(channel_bytes + data_bytes), SEEK_CUR);
    scan.valid_bytes += event_bytes;
    ++scan.events;
  }
  if (!scan.problem.empty())
    scan.problem += " at byte " + std::to_string(scan.valid_bytes);
  return scan;
}

void CopyCompleteEvents(const std::string& path, const LcmLogScan& scan, const std::string& copy) {
  std::unique_ptr<FILE, int (*)(FILE*)> in(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!in) throw std::runtime_error("cannot open LCM log " + path);
  std::unique_ptr<FILE, int (*)(FILE*)> out(std::fopen(copy.c_str(), "wb"), &std::fclose);
  if (!out) throw std::runtime_error("cannot write " + copy);
  std::vector<char> buffer(1 << 20);
  for (int64_t left = scan.valid_bytes; left > 0;) {
    const size_t n = size_t(std::min<int64_t>(left, int64_t(buffer.size())));
    if (std::fread(buffer.data(), 1, n, in.get()) != n) throw std::runtime_error("cannot read " + path);
    if (std::fwrite(buffer.data(), 1, n, out.get()) != n) throw std::runtime_error("cannot write " + copy);
    left -= int64_t(n);
  }
  if (std::fflush(out.get()) != 0) throw std::runtime_error("cannot write " + copy);
}

LcmLogRecovery RecoverLcmLog(const std::string& path, const LcmEventCheck& check) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open LCM log " + path);
  const std::string log((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw std::runtime_error("cannot read LCM log " + path);
  LcmLogRecovery recovery;
  recovery.file_bytes = int64_t(log.size());
  int64_t damage = -1;   // where the damaged stretch being crossed starts
  int64_t before = -1;   // the number of the last intact event (LCM's first is 0)
  for (int64_t at = 0; at < recovery.file_bytes;) {
    LcmLogEvent event;
    int64_t event_bytes = 0;
    if (const char* why = NotAnIntactEvent(log, at, check, &event, &event_bytes)) {
      if (damage < 0) {
        damage = at;
        if (recovery.first_damage.empty()) recovery.first_damage = why + (" at byte " + std::to_string(at));
      }
      ++at;
      continue;
    }
    if (damage >= 0) {
      recovery.lost_bytes += at - damage;
      recovery.lost_events += LostBetween(before, event.eventnum, at - damage);
      damage = -1;
    }
    before = event.eventnum;
    recovery.events.push_back(std::move(event));
    at += event_bytes;
  }
  if (damage >= 0) {
    recovery.lost_bytes += recovery.file_bytes - damage;
    recovery.lost_events += 1;
  }
  return recovery;
}

std::string EncodeLcmLog(const std::vector<LcmLogEvent>& events) {
  std::string log;
  for (size_t n = 0; n < events.size(); ++n) {
    const LcmLogEvent& event = events[n];
    AppendBigEndian(kSyncWord, 4, &log);
    AppendBigEndian(uint64_t(n), 8, &log);
    AppendBigEndian(uint64_t(event.timestamp), 8, &log);
    AppendBigEndian(event.channel.size(), 4, &log);
    AppendBigEndian(event.data.size(), 4, &log);
    log += event.channel;
    log.append(event.data.begin(), event.data.end());
  }
  return log;
}

std::string LcmFileUrlPath(const std::string& url) {
  const std::string scheme = "file://";
  if (url.compare(0, scheme.size(), scheme) != 0) return "";
  const std::string rest = url.substr(scheme.size());
  return rest.substr(0, rest.find('?'));
}

std::string LcmFileUrlWithPath(const std::string& url, const std::string& path) {
  const size_t query = url.find('?');
  return "file://" + path + (query == std::string::npos ? "" : url.substr(query));
}

}  // namespace ws

