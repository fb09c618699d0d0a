// stereo-view's page server core: HTTP/1.1 on one poll() thread, made to
// stay up under hostile input (docs/security.md, The page server).
//
// Why not cpp-httplib (which it replaced): httplib 0.11.4 grows the request
// line without limit (1 GB of RSS for 926 MB sent), gives each connection a
// thread for as long as it is open (16 idle sockets held the page for 4.5 s),
// reads a body whole before it can be refused, and keeps the socket private,
// so a gate in front of it cannot hand it a socket it has checked. Here:
//   - A head (view/http_head.h) is parsed from what has come, every time
//     something comes; it never grows past kMaxHead, a body past
//     Limits::body (refused by its Content-Length, before it is read).
//   - A connection costs a buffer, not a thread: idle or slow ones wait in
//     poll() and are closed at their deadline. A new connection is always
//     taken: at the cap of its client address that client's oldest
//     connection waiting for a request is closed (its oldest at all when
//     none waits: a response it does not read), at the cap in all the
//     busiest client's. So a flood of sockets pushes out itself, not a
//     page's next request.
//   - Only the names the server is reached by are served (view/host_check.h),
//     403 for the others: a page of another site cannot read the rig, or
//     command it, by DNS rebinding.
//   - Writes never block the loop; a response that makes no progress for
//     Limits::write_stall is dropped.
//   - A long-lived response (the page's event stream) is handed, with its
//     socket, to a thread of its own, which writes with a send timeout.
// The handler runs on the loop's thread: it answers from memory, at once.
#pragma once

#include <atomic>
#include <chrono>
#include <functional>
#include <list>
#include <memory>
#include <string>
#include <string_view>
#include <thread>
#include <utility>
#include <vector>

#include "view/http_head.h"

namespace ws::view {

struct HttpRequest {
  HttpHead head;
  std::string body;  // at most Limits::body bytes
};

struct HttpResponse {
  // Writes `bytes` to a handed-over socket (blocking, with a send timeout);
  // false once the browser is gone or has stopped reading.
  using Write = std::function<bool(std::string_view bytes)>;

  int status = 200;
  std::string content_type = "text/plain";
  std::vector<std::pair<std::string, std::string>> fields;  // more header fields
  std::string body;
  // A body kept elsewhere (a page's file, a blob) and what keeps it alive
  // (null: it outlives the server); sent instead of `body` when not empty.
  std::string_view shared_body;
  std::shared_ptr<const void> owner;
  // A stream: after the head, called on a thread of its own with the socket
  // until it returns; the connection then closes (the body ends with it).
  std::function<void(const Write&)> stream;

  void Text(int status_code, std::string text, std::string type = "text/plain");
};

class HttpServer {
 public:
  struct Limits {
    size_t body = 4096;                         // 413 beyond, before reading it
    std::chrono::milliseconds head{10000};      // from the first byte of a request to its last
    std::chrono::milliseconds idle{5000};       // an open connection between requests
    std::chrono::milliseconds write_stall{10000};  // a response that makes no progress
    std::chrono::milliseconds stream_send{5000};   // a stream's write (SO_SNDTIMEO)
    int per_client = 64;                        // connections of one address
    int total = 256;                            // connections in all (streams apart)
    int send_buffer = 32 * 1024;                // SO_SNDBUF of each connection (the kernel doubles it)
  };
  using Handler = std::function<void(const HttpRequest&, HttpResponse&)>;

  // Binds to address:port (0: any free port); throws when it cannot. Serves
  // from a thread of its own until destroyed.
  HttpServer(const std::string& address, int port, Handler handler, Limits limits);
  HttpServer(const HttpServer&) = delete;
  HttpServer& operator=(const HttpServer&) = delete;
  // Closes every connection and joins the streams' threads: whatever ends a
  // stream (EventHub::Close) must have been called first.
  ~HttpServer();
  int port() const { return port_; }

 private:
  struct Connection;
  struct Stream {
    std::thread thread;
    std::shared_ptr<std::atomic<bool>> done;
  };

  void Loop();
  void Accept();
  // Reads what has come and answers each complete request; false: close it.
  bool Read(Connection& c);
  bool Answer(Connection& c);
  // Writes what the socket takes; false: close it. The connection waits for
  // its next request (Answer) once all is sent.
  bool Flush(Connection& c);
  void Reply(Connection& c, HttpResponse& response, bool keep_alive);
  // Closes a connection of `client`: the oldest waiting for a request, else the oldest.
  void MakeRoom(const std::string& client);
  // The client address with the most connections.
  std::string Busiest() const;
  void StartStream(Connection& c, HttpResponse& response);

  Handler handler_;
  Limits limits_;
  int listener_ = -1, port_ = 0;
  int wake_[2] = {-1, -1};  // a pipe: the destructor's byte ends Loop()
  std::list<Connection> connections_;
  std::list<Stream> streams_;
  std::thread thread_;
};

}  // namespace ws::view
