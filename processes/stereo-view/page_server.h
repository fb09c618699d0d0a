// stereo-view's HTTP side (cpp-httplib): the page and its scripts, three.js
// from Debian's libjs-three, the live events by Server-Sent Events, and the
// page's commands.
//
//   GET  /                 the page            GET /events   the event stream
//   GET  /view.js, /view.css, /three.min.js, /OrbitControls.js
//   GET  /blob/ID          an image or a cloud an event names (view/blob_store.h);
//                          404 once forgotten
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
#include <utility>
#include <vector>

#include "runtime/process.h"
#include "static_asset.h"
#include "view/blob_store.h"
#include "view/event_hub.h"
#include "view/view_node.h"

namespace httplib {
class Server;
}

namespace ws::view {

class PageServer {
 public:
  static constexpr int kMaxStreams = 8;
  static constexpr int kSendBufferBytes = 32 * 1024;  // the kernel doubles it

  // Reads three.js (throws naming the package when it is missing) and binds
  // to address:port, any free port for 0 (throws when it cannot); serves
  // from a thread of its own.
  PageServer(Process& process, EventHub& hub, const BlobStore& blobs, ViewNode& node, const std::string& address,
             int port, const std::string& three_dir);
  // Closes the streams and stops serving.
  ~PageServer();
  int port() const { return port_; }

 private:
  void Routes();

  Process& process_;
  EventHub& hub_;
  const BlobStore& blobs_;
  ViewNode& node_;
  std::vector<std::pair<std::string, StaticAsset>> assets_;  // path, file
  std::unique_ptr<httplib::Server> server_;
  int port_ = 0;
  std::atomic<int> streams_{0};
  std::thread thread_;
};

}  // namespace ws::view
