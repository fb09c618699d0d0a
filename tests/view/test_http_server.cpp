// The page server's core over real sockets on loopback: answers and
// keep-alive, limits refused before reading, a stream on its own thread,
// and idle sockets that do not keep a request from being answered.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "view/http_server.h"

namespace {

using ws::view::HttpRequest;
using ws::view::HttpResponse;
using ws::view::HttpServer;

int Connect(int port) {
  const int fd = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(uint16_t(port));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  const timeval timeout{10, 0};
  setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof timeout);
  EXPECT_EQ(connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
  return fd;
}

// Sends `request` and reads until `until` is in the reply, or the server
// closes, or 10 s pass; the reply.
std::string Exchange(int fd, const std::string& request, const std::string& until) {
  if (!request.empty()) {
    EXPECT_EQ(send(fd, request.data(), request.size(), MSG_NOSIGNAL), ssize_t(request.size()));
  }
  std::string reply;
  char buffer[4096];
  while (reply.find(until) == std::string::npos) {
    const ssize_t n = recv(fd, buffer, sizeof buffer, 0);
    if (n <= 0) break;
    reply.append(buffer, size_t(n));
  }
  return reply;
}

std::string Get(int port, const std::string& path) {
  return "GET " + path + " HTTP/1.1\r\nHost: localhost:" + std::to_string(port) + "\r\n\r\n";
}

class HttpServerTest : public ::testing::Test {
 protected:
  // Sets stop_ as EventHub::Close does for the page's streams.
  void Stop() {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
    changed_.notify_all();
  }
  // Waits up to `seconds` for a stream to end; how many have.
  int StreamsEnded(int seconds) {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait_for(lock, std::chrono::seconds(seconds), [this] { return streams_ended_ > 0; });
    return streams_ended_;
  }
  // Before the server, so that they outlive its stream threads.
  std::mutex mutex_;
  std::condition_variable changed_;
  bool stop_ = false;
  int streams_ended_ = 0;
  HttpServer server_{"127.0.0.1", 0,
                     [this](const HttpRequest& req, HttpResponse& res) {
                       if (req.head.path == "/stream") {
                         res.stream = [this](const HttpResponse::Write& write) {
                           // An event every 10 ms until stopped or the browser goes.
                           while (write("data: x\n\n")) {
                             std::unique_lock<std::mutex> lock(mutex_);
                             if (changed_.wait_for(lock, std::chrono::milliseconds(10), [this] { return stop_; })) break;
                           }
                           std::lock_guard<std::mutex> lock(mutex_);
                           streams_ended_ += 1;
                           changed_.notify_all();
                         };
                         return;
                       }
                       res.Text(200, req.head.path + ":" + req.body + ";");
                     },
                     HttpServer::Limits{}};
};

TEST_F(HttpServerTest, AnswersPipelinedRequestsOnOneConnection) {
  const int fd = Connect(server_.port());
  const std::string post = "POST /b HTTP/1.1\r\nHost: localhost\r\nContent-Length: 3\r\n\r\nxyz";
  const std::string reply = Exchange(fd, Get(server_.port(), "/a") + post, "/b:xyz;");
  EXPECT_NE(reply.find("HTTP/1.1 200 OK"), std::string::npos);
  EXPECT_LT(reply.find("/a:;"), reply.find("/b:xyz;"));
  close(fd);
}

TEST_F(HttpServerTest, RefusesPastTheLimitsBeforeReadingOn) {
  int fd = Connect(server_.port());
  EXPECT_EQ(Exchange(fd, "GET /" + std::string(10000, 'a'), "\r\n\r\n").substr(0, 13), "HTTP/1.1 414 ");
  close(fd);
  fd = Connect(server_.port());
  const std::string big = "POST / HTTP/1.1\r\nHost: localhost\r\nContent-Length: 100000000\r\n\r\n";
  EXPECT_EQ(Exchange(fd, big, "\r\n\r\n").substr(0, 13), "HTTP/1.1 413 ");
  close(fd);
  fd = Connect(server_.port());
  const std::string foreign = "GET / HTTP/1.1\r\nHost: rebind.example\r\n\r\n";
  EXPECT_EQ(Exchange(fd, foreign, "\r\n\r\n").substr(0, 13), "HTTP/1.1 403 ");
  close(fd);
}

TEST_F(HttpServerTest, AStreamRunsOnItsOwnThreadUntilTheBrowserGoes) {
  const int fd = Connect(server_.port());
  const std::string reply = Exchange(fd, Get(server_.port(), "/stream"), "data: x\n\ndata: x\n\n");
  EXPECT_EQ(reply.substr(0, 13), "HTTP/1.1 200 ");
  EXPECT_NE(reply.find("Connection: close"), std::string::npos);
  // Other requests are answered meanwhile.
  const int other = Connect(server_.port());
  EXPECT_NE(Exchange(other, Get(server_.port(), "/a"), "/a:;").find("/a:;"), std::string::npos);
  close(other);
  close(fd);
  EXPECT_EQ(StreamsEnded(10), 1);
}

TEST_F(HttpServerTest, IdleSocketsDoNotKeepARequestFromBeingAnswered) {
  std::vector<int> idle;
  for (int i = 0; i < 300; ++i) idle.push_back(Connect(server_.port()));
  const int fd = Connect(server_.port());
  EXPECT_NE(Exchange(fd, Get(server_.port(), "/a"), "/a:;").find("/a:;"), std::string::npos);
  close(fd);
  // The oldest of them were closed to make room (64 a client at most).
  char byte;
  EXPECT_EQ(recv(idle.front(), &byte, 1, 0), 0);
  for (int s : idle) close(s);
}

TEST_F(HttpServerTest, StopsWithAStreamOpen) {
  const int fd = Connect(server_.port());
  EXPECT_NE(Exchange(fd, Get(server_.port(), "/stream"), "data: x\n\n").find("data: x"), std::string::npos);
  Stop();
  close(fd);
}

}  // namespace
