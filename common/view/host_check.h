// Which names stereo-view's page is served by. A browser sends the name it
// reached the server by (Host) and, for a request a page makes, the page's
// site (Origin). A page of another site whose name was rebound to this
// machine's address (DNS rebinding) still sends its own name, so only these
// are served: localhost, 127.0.0.1, [::1], and the address the connection
// came in on (the --listen address, or with 0.0.0.0 the interface's). Any
// port, or none: an SSH tunnel may bring the page to another port, and a
// rebound name is refused by its name. A name of the machine (robot.local)
// is not among them: it is reached by its address.
#pragma once

#include <string_view>

namespace ws::view {

// `host`: a Host field. `local`: the connection's local address, numeric
// ("192.168.1.5", "::1").
bool HostAllowed(std::string_view host, std::string_view local);
// `origin`: an Origin field; `host`: the request's Host. Absent ("") is
// allowed (a browser sends none for the page's own GETs); else only the
// page's own site, "http://" and the Host ("null" and every other site not).
bool OriginAllowed(std::string_view origin, std::string_view host);

}  // namespace ws::view
