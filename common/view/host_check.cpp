#include "view/host_check.h"

#include <algorithm>
#include <cctype>
#include <string>

namespace ws::view {
namespace {

std::string Lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return out;
}

}  // namespace

bool HostAllowed(std::string_view host, std::string_view local) {
  std::string name = Lower(host);
  // A port: digits after the last ':' that is not inside an IPv6 address's brackets.
  const size_t colon = name.rfind(':');
  if (colon != std::string::npos && (name.find(']') == std::string::npos || colon > name.find(']'))) {
    const std::string port = name.substr(colon + 1);
    if (port.empty() || port.size() > 5 || !std::all_of(port.begin(), port.end(), ::isdigit)) return false;
    name.resize(colon);
  }
  const std::string own = local.find(':') == std::string_view::npos ? Lower(local) : "[" + Lower(local) + "]";
  return name == "localhost" || name == "127.0.0.1" || name == "[::1]" || name == own;
}

bool OriginAllowed(std::string_view origin, std::string_view host) {
  return origin.empty() || Lower(origin) == "http://" + Lower(host);
}

}  // namespace ws::view
