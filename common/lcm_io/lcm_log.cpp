#include "lcm_io/lcm_log.h"

#include <algorithm>
#include <cstdio>
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

