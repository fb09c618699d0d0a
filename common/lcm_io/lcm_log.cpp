#include "lcm_io/lcm_log.h"

#include <cstdio>
#include <memory>
#include <stdexcept>

namespace ws {
namespace {

constexpr uint32_t kSyncWord = 0xEDA1DA01;  // LCM's event log sync word
constexpr int64_t kHeaderBytes = 4 + 8 + 8 + 4 + 4;
constexpr int64_t kMaxChannelBytes = 256;

uint64_t BigEndian(const unsigned char* p, int n) {
  uint64_t v = 0;
  for (int i = 0; i < n; ++i) v = (v << 8) | p[i];
  return v;
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
    if (left < kHeaderBytes || std::fread(header, 1, kHeaderBytes, f.get()) != kHeaderBytes) {
      scan.problem = "truncated event header";
      break;
    }
    if (BigEndian(header, 4) != kSyncWord) {
      scan.problem = "bad sync word";
      break;
    }
    const int64_t channel_bytes = int64_t(BigEndian(header + 20, 4));
    const int64_t data_bytes = int64_t(BigEndian(header + 24, 4));
    if (channel_bytes <= 0 || channel_bytes > kMaxChannelBytes) {
      scan.problem = "bad channel length " + std::to_string(channel_bytes);
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

std::string LcmFileUrlPath(const std::string& url) {
  const std::string scheme = "file://";
  if (url.compare(0, scheme.size(), scheme) != 0) return "";
  const std::string rest = url.substr(scheme.size());
  return rest.substr(0, rest.find('?'));
}

}  // namespace ws
