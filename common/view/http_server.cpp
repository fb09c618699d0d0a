#include "view/http_server.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <map>
#include <stdexcept>

#include "view/host_check.h"

namespace ws::view {
namespace {

using Clock = std::chrono::steady_clock;

constexpr int kAcceptsPerTurn = 16;  // then the open connections' turn: a flood of connects does not starve them
constexpr std::chrono::milliseconds kDrain{2000};  // reading after a refusal, so the browser sees it (no RST)

const char* Reason(int status) {
  switch (status) {
    case 200: return "OK";
    case 400: return "Bad Request";
    case 403: return "Forbidden";
    case 404: return "Not Found";
    case 405: return "Method Not Allowed";
    case 413: return "Content Too Large";
    case 414: return "URI Too Long";
    case 431: return "Request Header Fields Too Large";
    case 501: return "Not Implemented";
    case 503: return "Service Unavailable";
    case 505: return "HTTP Version Not Supported";
    default: return status < 500 ? "Client Error" : "Server Error";
  }
}

// A socket address as text ("127.0.0.1", "::1"); an IPv4 one mapped to IPv6 as IPv4.
std::string AddressText(const sockaddr_storage& address) {
  char text[INET6_ADDRSTRLEN] = "";
  if (address.ss_family == AF_INET) {
    inet_ntop(AF_INET, &reinterpret_cast<const sockaddr_in&>(address).sin_addr, text, sizeof text);
  } else if (address.ss_family == AF_INET6) {
    const in6_addr& a6 = reinterpret_cast<const sockaddr_in6&>(address).sin6_addr;
    if (IN6_IS_ADDR_V4MAPPED(&a6))
      inet_ntop(AF_INET, &a6.s6_addr[12], text, sizeof text);
    else
      inet_ntop(AF_INET6, &a6, text, sizeof text);
  }
  return text;
}

std::string Head(int status, const std::string& content_type,
                 const std::vector<std::pair<std::string, std::string>>& fields) {
  std::string head = "HTTP/1.1 " + std::to_string(status) + " " + Reason(status) + "\r\nContent-Type: " + content_type + "\r\n";
  for (const auto& [name, value] : fields) head += name + ": " + value + "\r\n";
  return head;
}

}  // namespace

void HttpResponse::Text(int status_code, std::string text, std::string type) {
  status = status_code;
  body = std::move(text);
  content_type = std::move(type);
}

struct HttpServer::Connection {
  enum class State { kRequest, kWriting, kDraining };

  int fd = -1;
  std::string client, local;  // numeric addresses
  State state = State::kRequest;
  Clock::time_point since;     // waiting for a request since (accepted, or the last response sent)
  Clock::time_point deadline;  // closed then
  std::string in;              // at most kMaxHead + Limits::body
  std::string out;             // the response's head (and a body of its own)
  std::string_view out_body;   // a shared body, after `out`
  std::shared_ptr<const void> owner;
  size_t sent = 0;  // of out, then of out_body
  bool keep_alive = true;
};

HttpServer::HttpServer(const std::string& address, int port, Handler handler, Limits limits)
    : handler_(std::move(handler)), limits_(limits) {
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  hints.ai_flags = AI_PASSIVE;
  addrinfo* found = nullptr;
  const std::string where = address + ":" + std::to_string(port);
  if (getaddrinfo(address.c_str(), std::to_string(port).c_str(), &hints, &found) != 0 || !found)
    throw std::runtime_error("cannot listen on " + where + ": not an address");
  listener_ = socket(found->ai_family, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  // SO_REUSEADDR, not SO_REUSEPORT: a second server on this port is refused,
  // not handed half the browsers.
  const int yes = 1;
  const bool bound = listener_ >= 0 && setsockopt(listener_, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes) == 0 &&
                     bind(listener_, found->ai_addr, found->ai_addrlen) == 0 && listen(listener_, SOMAXCONN) == 0;
  const int error = errno;
  freeaddrinfo(found);
  sockaddr_storage own{};
  socklen_t own_length = sizeof own;
  if (!bound || getsockname(listener_, reinterpret_cast<sockaddr*>(&own), &own_length) != 0 || pipe2(wake_, O_CLOEXEC) != 0) {
    if (listener_ >= 0) close(listener_);
    throw std::runtime_error("cannot listen on " + where + ": " + std::strerror(error) +
                             " (in use by another program? another --port)");
  }
  port_ = ntohs(own.ss_family == AF_INET6 ? reinterpret_cast<sockaddr_in6&>(own).sin6_port
                                          : reinterpret_cast<sockaddr_in&>(own).sin_port);
  thread_ = std::thread([this] { Loop(); });
}

HttpServer::~HttpServer() {
  const char stop = 1;
  if (write(wake_[1], &stop, 1) != 1) std::perror("stereo-view: cannot stop the page server");
  thread_.join();
  for (Connection& c : connections_) close(c.fd);
  for (Stream& s : streams_) s.thread.join();
  close(listener_);
  close(wake_[0]);
  close(wake_[1]);
}

void HttpServer::Loop() {
  std::vector<pollfd> polled;
  std::vector<std::list<Connection>::iterator> polled_connections;
  for (;;) {
    polled.assign({{wake_[0], POLLIN, 0}, {listener_, POLLIN, 0}});
    polled_connections.clear();
    Clock::time_point next = Clock::now() + std::chrono::seconds(1);
    for (auto it = connections_.begin(); it != connections_.end(); ++it) {
      polled.push_back({it->fd, short(it->state == Connection::State::kWriting ? POLLOUT : POLLIN), 0});
      polled_connections.push_back(it);
      next = std::min(next, it->deadline);
    }
    const auto wait = std::chrono::duration_cast<std::chrono::milliseconds>(next - Clock::now()).count();
    if (poll(polled.data(), polled.size(), int(std::max<int64_t>(0, wait) + 1)) < 0 && errno != EINTR)
      std::perror("stereo-view: poll");
    if (polled[0].revents) return;
    const auto now = Clock::now();
    for (size_t i = 0; i < polled_connections.size(); ++i) {
      Connection& c = *polled_connections[i];
      bool open = true;
      if (polled[i + 2].revents)
        open = c.state == Connection::State::kWriting ? Flush(c) && Answer(c) : Read(c);
      if (open && c.deadline <= now) open = false;  // idle, slow, or not reading what it asked for
      if (!open) {
        if (c.fd >= 0) close(c.fd);
        connections_.erase(polled_connections[i]);
      }
    }
    if (polled[1].revents) Accept();
  }
}

void HttpServer::Accept() {
  for (int turn = 0; turn < kAcceptsPerTurn; ++turn) {
    sockaddr_storage peer{}, own{};
    socklen_t peer_length = sizeof peer, own_length = sizeof own;
    const int fd = accept4(listener_, reinterpret_cast<sockaddr*>(&peer), &peer_length, SOCK_NONBLOCK | SOCK_CLOEXEC);
    if (fd < 0) {
      // Out of descriptors: room is made for the next one (the listener stays ready).
      if (errno == EMFILE || errno == ENFILE) MakeRoom(Busiest());
      return;
    }
    Connection c;
    c.fd = fd;
    c.client = AddressText(peer);
    if (getsockname(fd, reinterpret_cast<sockaddr*>(&own), &own_length) == 0) c.local = AddressText(own);
    const auto mine = std::count_if(connections_.begin(), connections_.end(),
                                    [&](const Connection& other) { return other.client == c.client; });
    if (mine >= limits_.per_client) MakeRoom(c.client);
    if (int(connections_.size()) >= limits_.total) MakeRoom(Busiest());
    setsockopt(fd, SOL_SOCKET, SO_SNDBUF, &limits_.send_buffer, sizeof limits_.send_buffer);
    const int yes = 1;
    setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &yes, sizeof yes);
    c.since = Clock::now();
    c.deadline = c.since + limits_.idle;
    connections_.push_back(std::move(c));
  }
}

void HttpServer::MakeRoom(const std::string& client) {
  // The oldest waiting for a request, else the oldest (a response it does not read).
  const auto before = [](const Connection& a, const Connection& b) {
    const bool a_waits = a.state != Connection::State::kWriting, b_waits = b.state != Connection::State::kWriting;
    return a_waits != b_waits ? a_waits : a.since < b.since;
  };
  auto chosen = connections_.end();
  for (auto it = connections_.begin(); it != connections_.end(); ++it)
    if (it->client == client && (chosen == connections_.end() || before(*it, *chosen))) chosen = it;
  if (chosen == connections_.end()) return;
  close(chosen->fd);
  connections_.erase(chosen);
}

std::string HttpServer::Busiest() const {
  std::map<std::string, int> count;
  for (const Connection& c : connections_) ++count[c.client];
  const auto most = std::max_element(count.begin(), count.end(),
                                     [](const auto& a, const auto& b) { return a.second < b.second; });
  return most == count.end() ? "" : most->first;
}

bool HttpServer::Read(Connection& c) {
  char buffer[16384];
  // Never more than a head and a body: past that the head or the body is refused.
  const size_t room = kMaxHead + limits_.body - c.in.size();
  const ssize_t n = recv(c.fd, buffer, std::min(sizeof buffer, room), 0);
  if (n == 0) return false;
  if (n < 0) return errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR;
  if (c.state == Connection::State::kDraining) return true;  // dropped: only the reply counts now
  if (c.in.empty()) c.deadline = Clock::now() + limits_.head;  // a request begins
  c.in.append(buffer, size_t(n));
  return Answer(c);
}

bool HttpServer::Answer(Connection& c) {
  while (c.state == Connection::State::kRequest && !c.in.empty()) {
    HeadParse parse = ParseHead(c.in);
    HttpResponse response;
    if (parse.state == HeadParse::State::kIncomplete) return true;
    if (parse.state == HeadParse::State::kRefused) {
      response.Text(parse.status, parse.why);
      Reply(c, response, false);
      return Flush(c);
    }
    const HttpHead& head = parse.head;
    if (head.content_length > int64_t(limits_.body)) {
      response.Text(413, "a body is at most " + std::to_string(limits_.body) + " bytes");
      Reply(c, response, false);
      return Flush(c);
    }
    if (c.in.size() < parse.length + size_t(head.content_length)) return true;  // the body is coming
    HttpRequest request{std::move(parse.head), c.in.substr(parse.length, size_t(head.content_length))};
    c.in.erase(0, parse.length + size_t(head.content_length));
    const std::string host = request.head.Field("host");
    if (!HostAllowed(host, c.local) || !OriginAllowed(request.head.Field("origin"), host)) {
      response.Text(403, "served only as http://localhost:" + std::to_string(port_) +
                             "/ (or 127.0.0.1, [::1], or the address it listens on), to its own page");
    } else {
      try {
        handler_(request, response);
      } catch (const std::exception& e) {
        response.Text(500, e.what());
      }
    }
    if (response.stream && response.status == 200) {
      StartStream(c, response);
      return false;
    }
    Reply(c, response, request.head.KeepAlive() && response.status != 403);
    if (!Flush(c)) return false;
  }
  return true;
}

void HttpServer::Reply(Connection& c, HttpResponse& response, bool keep_alive) {
  const std::string_view body = response.shared_body.empty() ? std::string_view(response.body) : response.shared_body;
  c.out = Head(response.status, response.content_type, response.fields) +
          "Content-Length: " + std::to_string(body.size()) + "\r\nConnection: " + (keep_alive ? "keep-alive" : "close") +
          "\r\n\r\n";
  if (response.shared_body.empty()) {
    c.out += response.body;
    c.out_body = {};
  } else {
    c.out_body = response.shared_body;
    c.owner = std::move(response.owner);
  }
  c.sent = 0;
  c.keep_alive = keep_alive;
  c.state = Connection::State::kWriting;
  c.deadline = Clock::now() + limits_.write_stall;
}

bool HttpServer::Flush(Connection& c) {
  while (c.sent < c.out.size() + c.out_body.size()) {
    const bool in_head = c.sent < c.out.size();
    const char* from = in_head ? c.out.data() + c.sent : c.out_body.data() + (c.sent - c.out.size());
    const size_t left = in_head ? c.out.size() - c.sent : c.out_body.size() - (c.sent - c.out.size());
    const ssize_t n = send(c.fd, from, left, MSG_NOSIGNAL);
    if (n < 0) return errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR;
    c.sent += size_t(n);
    c.deadline = Clock::now() + limits_.write_stall;
  }
  c.out.clear();
  c.out_body = {};
  c.owner.reset();
  if (!c.keep_alive) {
    // What the browser still sends is read and dropped for a while, so that
    // closing does not reset the connection before it has read the reply.
    shutdown(c.fd, SHUT_WR);
    c.state = Connection::State::kDraining;
    c.in.clear();
    c.deadline = Clock::now() + kDrain;
    return true;
  }
  c.state = Connection::State::kRequest;
  c.since = Clock::now();
  c.deadline = c.since + (c.in.empty() ? limits_.idle : limits_.head);  // a pipelined one: head
  return true;
}

void HttpServer::StartStream(Connection& c, HttpResponse& response) {
  streams_.remove_if([](Stream& s) {
    if (!*s.done) return false;
    s.thread.join();
    return true;
  });
  const int fd = c.fd;
  c.fd = -1;  // the stream's now
  const int flags = fcntl(fd, F_GETFL);
  fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
  const timeval timeout{time_t(limits_.stream_send.count() / 1000), suseconds_t(limits_.stream_send.count() % 1000 * 1000)};
  setsockopt(fd, SOL_SOCKET, SO_SNDTIMEO, &timeout, sizeof timeout);
  // No length: the stream's body ends when the connection does.
  std::string head = Head(200, response.content_type, response.fields) + "Connection: close\r\n\r\n";
  auto done = std::make_shared<std::atomic<bool>>(false);
  streams_.push_back({std::thread([fd, done, head = std::move(head), stream = std::move(response.stream)] {
                        bool broken = false;  // a write that failed: the stream's bytes would be garbled
                        const HttpResponse::Write write = [fd, &broken](std::string_view bytes) {
                          while (!broken && !bytes.empty()) {
                            const ssize_t n = send(fd, bytes.data(), bytes.size(), MSG_NOSIGNAL);
                            if (n > 0) bytes.remove_prefix(size_t(n));
                            broken = n <= 0 && errno != EINTR;
                          }
                          return !broken;
                        };
                        write(head);
                        stream(write);  // even when the head failed: it ends at its first write
                        close(fd);
                        *done = true;
                      }),
                      done});
}

}  // namespace ws::view
