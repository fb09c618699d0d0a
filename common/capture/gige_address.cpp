#include "capture/gige_address.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <ifaddrs.h>
#include <net/if.h>
#include <netinet/in.h>
#include <sys/file.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <thread>

#include "capture/camera_error.h"

namespace ws {
namespace {

constexpr uint16_t kGvcpPort = 3956;
constexpr char kAliasHint[] = "add an address, e.g. 'ip addr add 127.0.0.2/8 dev lo'";

int Rank(const std::string& address) {
  if (address == "127.0.0.1") return 0;
  return address.rfind("127.", 0) == 0 ? 1 : 2;
}

}  // namespace

std::vector<std::string> LocalIpv4Addresses() {
  std::vector<std::string> addresses;
  ifaddrs* list = nullptr;
  if (getifaddrs(&list) != 0) return addresses;
  for (const ifaddrs* entry = list; entry; entry = entry->ifa_next) {
    if (!entry->ifa_addr || entry->ifa_addr->sa_family != AF_INET) continue;
    if (!(entry->ifa_flags & IFF_UP)) continue;
    char text[INET_ADDRSTRLEN];
    const auto* address = reinterpret_cast<const sockaddr_in*>(entry->ifa_addr);
    inet_ntop(AF_INET, &address->sin_addr, text, sizeof text);
    if (std::find(addresses.begin(), addresses.end(), text) == addresses.end())
      addresses.emplace_back(text);
  }
  freeifaddrs(list);
  std::stable_sort(addresses.begin(), addresses.end(),
                   [](const std::string& a, const std::string& b) { return Rank(a) < Rank(b); });
  return addresses;
}

GvcpPortClaim::GvcpPortClaim(const std::string& address, std::chrono::milliseconds wait, const Waiting& waiting)
    : address_(address) {
  const auto local = LocalIpv4Addresses();
  if (std::find(local.begin(), local.end(), address) == local.end())
    throw CameraError("fake camera address " + address + " is not an address of this host; " +
                      kAliasHint);
  const std::string path = "/tmp/widestereo-gige-" + address + ".lock";
  lock_fd_ = open(path.c_str(), O_RDONLY | O_CREAT | O_CLOEXEC, 0666);
  if (lock_fd_ < 0) throw CameraError("cannot open " + path + ": " + std::strerror(errno));
  const auto deadline = std::chrono::steady_clock::now() + wait;
  for (bool told = false; flock(lock_fd_, LOCK_EX | LOCK_NB) != 0; told = true) {
    if (!told && waiting && wait.count() > 0) {
      char seconds[32];
      std::snprintf(seconds, sizeof seconds, "%g", wait.count() / 1000.0);
      waiting("waiting up to " + std::string(seconds) + " s for " + address +
              ": another fake camera serves there (it holds " + path + ")");
    }
    if (std::chrono::steady_clock::now() >= deadline) {
      close(lock_fd_);
      throw CameraError("another fake camera serves at " + address + " (it holds " + path + ")");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

GvcpPortClaim::~GvcpPortClaim() { close(lock_fd_); }

void GvcpPortClaim::CheckPortFree() const {
  const int fd = socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  if (fd < 0) throw CameraError(std::string("cannot open a UDP socket: ") + std::strerror(errno));
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(kGvcpPort);
  inet_pton(AF_INET, address_.c_str(), &address.sin_addr);
  const int result = bind(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address);
  const int error = errno;
  close(fd);
  if (result != 0)
    throw CameraError("cannot serve a camera at " + address_ + ": UDP port 3956 " +
                      (error == EADDRINUSE
                           ? std::string("is taken by another camera; ") + kAliasHint
                           : std::string(std::strerror(error))));
}

bool GvcpAddressFree(const std::string& address) {
  try {
    const GvcpPortClaim claim(address, std::chrono::milliseconds(0));
    claim.CheckPortFree();
    return true;
  } catch (const CameraError&) {
    return false;
  }
}

}  // namespace ws
