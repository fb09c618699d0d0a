// Local IPv4 addresses for fake GigE Vision cameras.
//
// A GigE Vision camera answers control packets on UDP port 3956 of its
// address, so two cameras served from one host need two addresses: on the
// same one the second camera cannot bind the port, and a client that opens it
// silently talks to the first. Loopback aliases are the cleanest choice:
//   ip addr add 127.0.0.2/8 dev lo
// Without one, another interface's address works too (traffic to this host's
// own addresses stays inside it), but a camera there also answers discovery
// from that network.
#pragma once

#include <chrono>
#include <functional>
#include <string>
#include <vector>

namespace ws {

// The IPv4 addresses of this host's interfaces that are up: 127.0.0.1 first,
// then other loopback addresses, then the rest, each once.
std::vector<std::string> LocalIpv4Addresses();

// Holds UDP port 3956 of one local address for one fake camera: an exclusive
// lock file (/tmp/widestereo-gige-ADDRESS.lock), waited for up to `wait`, so
// that fake cameras of concurrent processes (tests run in parallel) take
// turns; `waiting`, if given, is told once what it waits for. Throws
// CameraError when the address is not local or the lock is not free in time.
class GvcpPortClaim {
 public:
  using Waiting = std::function<void(const std::string& what)>;
  GvcpPortClaim(const std::string& address, std::chrono::milliseconds wait, const Waiting& waiting = {});
  ~GvcpPortClaim();
  GvcpPortClaim(const GvcpPortClaim&) = delete;
  GvcpPortClaim& operator=(const GvcpPortClaim&) = delete;

  // Throws CameraError when something else (another program's camera) has
  // the port bound; call it before serving on the address.
  void CheckPortFree() const;

 private:
  std::string address_;
  int lock_fd_ = -1;
};

// Whether a fake camera could serve at `address` now: a local address, no
// other fake camera holding it and nothing bound to its UDP port 3956. A
// moment's answer: another process may take it next.
bool GvcpAddressFree(const std::string& address);

}  // namespace ws
