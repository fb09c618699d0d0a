#include "view/host_check.h"

#include <algorithm>
#include <cctype>
#include <string>

namespace ws::view {

bool HostAllowed(std::string_view host, std::string_view local, int port) {
  std::string name(host);
  std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  const std::string suffix = ":" + std::to_string(port);
  if (name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
    name.resize(name.size() - suffix.size());
  else if (port != 80)
    return false;
  const std::string own = local.find(':') == std::string_view::npos ? std::string(local) : "[" + std::string(local) + "]";
  return name == "localhost" || name == "127.0.0.1" || name == "[::1]" || name == own;
}

bool OriginAllowed(std::string_view origin, std::string_view local, int port) {
  static constexpr std::string_view kScheme = "http://";
  if (origin.empty()) return true;
  return origin.substr(0, kScheme.size()) == kScheme && HostAllowed(origin.substr(kScheme.size()), local, port);
}

}  // namespace ws::view
