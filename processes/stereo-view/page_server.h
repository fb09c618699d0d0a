// stereo-view's HTTP side (cpp-httplib): the page and its scripts, three.js
// from Debian's libjs-three, the live events by Server-Sent Events, and the
// page's commands.
//
//   GET  /                 the page            GET /events   the event stream
//   GET  /view.js, /view.css, /three.min.js, /OrbitControls.js
//   POST /command          {"command": "solve"}: 403 with the reason when
//                          refused (no rig key), 400 for anything else
//
// A POST must carry the header X-Widestereo-Page: 1, which a page of another
// site cannot send without the browser asking first (CORS), so no other page
// a user has open can press the buttons. At most kMaxStreams event streams at
// once (503 beyond), so that the page's files are always served.
#pragma once

#include <atomic>
#include <memory>
#include <string>
#include <thread>

#include "runtime/process.h"
#include "view/event_hub.h"
#include "view/view_node.h"

namespace httplib {
class Server;
}

namespace ws::view {

class PageServer {
 public:
  static constexpr int kMaxStreams = 8;

  // Reads three.js (throws naming the package when it is missing) and binds
  // to address:port, any free port for 0 (throws when it cannot); serves
  // from a thread of its own.
  PageServer(Process& process, EventHub& hub, ViewNode& node, const std::string& address, int port,
             const std::string& three_dir);
  // Closes the streams and stops serving.
  ~PageServer();
  int port() const { return port_; }

 private:
  void Routes();

  Process& process_;
  EventHub& hub_;
  ViewNode& node_;
  std::string three_js_, orbit_controls_js_;
  std::unique_ptr<httplib::Server> server_;
  int port_ = 0;
  std::atomic<int> streams_{0};
  std::thread thread_;
};

}  // namespace ws::view
