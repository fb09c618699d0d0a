// stereo-view's HTTP side (view/http_server.h): the page and its scripts, three.js
// from Debian's libjs-three, the live events by Server-Sent Events, and the
// page's commands.
//
//   GET  /                 the page
//   GET  /events?view=V    the event stream of a page showing view V
//                          (calibration or depth; none: both), 400 for another
//   GET  /view.js, /view.css, /cloud3d.js, /freshness.js, /process_table.js, /view_list.js,
//        /three.min.js, /OrbitControls.js
//   GET  /blob/ID          an image or a cloud an event names (view/blob_store.h);
//                          404 once forgotten
//   POST /command          {"command": "solve"}, or {"command": "remove",
//                          "frame": ID, "utime": US}: 403 with the reason when
//                          refused (no rig key), 400 for anything else
//
// A POST must carry the header X-Widestereo-Page: 1, which a page of another
// site cannot send without the browser asking first (CORS), so no other page
// a user has open can press the buttons. A command's body is at most
// kMaxBody bytes (413 beyond, unread), so its JSON is small and shallow
// before it is parsed. At most kMaxStreams event streams at once (503
// beyond). Every request names the server as it is reached (Host, Origin:
// view/host_check.h), 403 otherwise.
#pragma once

#include <atomic>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "runtime/process.h"
#include "static_asset.h"
#include "view/audience.h"
#include "view/blob_store.h"
#include "view/event_hub.h"
#include "view/http_server.h"
#include "view/view_node.h"

namespace ws::view {

class PageServer {
 public:
  static constexpr int kMaxStreams = 8;
  static constexpr size_t kMaxBody = 1024;  // {"command": "restore"} is 22

  // Reads three.js (throws naming the package when it is missing) and binds
  // to address:port, any free port for 0 (throws when it cannot); serves
  // from threads of its own.
  PageServer(Process& process, EventHub& hub, const BlobStore& blobs, Audience& audience, ViewNode& node,
             const std::string& address, int port, const std::string& three_dir);
  // Closes the streams and stops serving.
  ~PageServer();
  int port() const { return server_->port(); }

 private:
  void Handle(const HttpRequest& req, HttpResponse& res);
  void ServeBlob(const std::string& id, HttpResponse& res);
  void Events(const HttpHead& req, HttpResponse& res);
  void Command(const HttpRequest& req, HttpResponse& res);

  Process& process_;
  EventHub& hub_;
  const BlobStore& blobs_;
  Audience& audience_;
  ViewNode& node_;
  std::vector<std::pair<std::string, StaticAsset>> assets_;  // path, file
  std::atomic<int> streams_{0};
  std::unique_ptr<HttpServer> server_;  // last: it stops before what it serves goes
};

}  // namespace ws::view
