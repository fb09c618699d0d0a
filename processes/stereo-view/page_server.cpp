#include "page_server.h"

#include <sys/socket.h>

#include <fstream>
#include <sstream>

#include <httplib.h>
#include <nlohmann/json.hpp>

#include "web_assets.h"

namespace ws::view {
namespace {

std::string ReadFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw std::runtime_error("cannot read " + path +
                             ": install Debian's libjs-three (make deps), or give its folder with --three-dir");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

PageServer::PageServer(Process& process, EventHub& hub, const BlobStore& blobs, ViewNode& node,
                       const std::string& address, int port, const std::string& three_dir)
    : process_(process),
      hub_(hub),
      blobs_(blobs),
      node_(node),
      assets_{{"/", {kIndexHtml, "text/html; charset=utf-8"}},
              {"/view.js", {kViewJs, "text/javascript"}},
              {"/view.css", {kViewCss, "text/css"}},
              {"/three.min.js", {ReadFile(three_dir + "/build/three.min.js"), "text/javascript"}},
              {"/OrbitControls.js",
               {ReadFile(three_dir + "/examples/js/controls/OrbitControls.js"), "text/javascript"}}},
      server_(std::make_unique<httplib::Server>()) {
  server_->new_task_queue = [] { return new httplib::ThreadPool(kMaxStreams + 8); };
  server_->set_socket_options([](int sock) {
    // Not httplib's SO_REUSEPORT: a second server on this port is refused,
    // not handed half the browsers.
    const int yes = 1;
    setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
    // A small send buffer (kept by every accepted socket): what a slow browser
    // has not read stays here, not in the kernel, so it gets the newest events
    // and not a backlog, and a stalled one is found (the write times out).
    setsockopt(sock, SOL_SOCKET, SO_SNDBUF, &kSendBufferBytes, sizeof kSendBufferBytes);
  });
  Routes();
  port_ = port == 0 ? server_->bind_to_any_port(address) : server_->bind_to_port(address, port) ? port : -1;
  if (port_ <= 0)
    throw std::runtime_error("cannot listen on " + address + ":" + std::to_string(port) +
                             " (in use by another program? another --port)");
  thread_ = std::thread([this] { server_->listen_after_bind(); });
  process_.log().Info("the page: http://" + address + ":" + std::to_string(port_) + "/");
}

PageServer::~PageServer() {
  hub_.Close();
  server_->stop();
  if (thread_.joinable()) thread_.join();
}

void PageServer::Routes() {
  for (const auto& [path, asset] : assets_)
    server_->Get(path, [&asset = asset](const httplib::Request& req, httplib::Response& res) { asset.Serve(req, res); });

  // The id is at most 18 digits, so it always fits an int64.
  server_->Get(R"(/blob/(\d{1,18}))", [this](const httplib::Request& req, httplib::Response& res) {
    const auto blob = blobs_.Get(std::stoll(req.matches[1].str()));
    if (!blob) {
      res.status = 404;
      return res.set_content("no longer kept: the page shows the next one", "text/plain");
    }
    res.set_header("Cache-Control", "private, max-age=60, immutable");  // a blob never changes
    res.set_content(reinterpret_cast<const char*>(blob->bytes.data()), blob->bytes.size(), blob->content_type.c_str());
  });

  server_->Get("/events", [this](const httplib::Request&, httplib::Response& res) {
    if (++streams_ > kMaxStreams) {
      --streams_;
      res.status = 503;
      res.set_content("too many pages open on this stereo-view", "text/plain");
      return;
    }
    res.set_header("Cache-Control", "no-cache");
    auto cursor = std::make_shared<EventHub::Cursor>();
    auto& browsers = process_.Counters(kBrowserCounters);
    res.set_chunked_content_provider(
        "text/event-stream",
        [this, cursor, &browsers](size_t, httplib::DataSink& sink) {
          int64_t skipped = 0;
          const auto events = hub_.Next(*cursor, std::chrono::seconds(1), &skipped);
          browsers.skipped += skipped;
          if (hub_.closed()) return false;
          std::string text = events.empty() ? ": still here\n\n" : "";
          for (const Event& event : events) text += "event: " + event.topic + "\ndata: " + *event.json + "\n\n";
          if (!sink.write(text.data(), text.size())) return false;
          browsers.published += int64_t(events.size());
          return true;
        },
        [this, cursor, &browsers](bool) {
          browsers.skipped += hub_.Unsent(*cursor);
          --streams_;
        });
  });

  server_->Post("/command", [this](const httplib::Request& req, httplib::Response& res) {
    auto reply = [&res](int status, const std::string& error) {
      res.status = status;
      res.set_content(nlohmann::json{{"error", error}}.dump(), "application/json");
    };
    if (req.get_header_value("X-Widestereo-Page") != "1")
      return reply(400, "a command comes from the page (header X-Widestereo-Page: 1)");
    const auto body = nlohmann::json::parse(req.body, nullptr, false);
    if (!body.is_object() || !body.contains("command") || !body["command"].is_string() || body.size() != 1)
      return reply(400, "the body is {\"command\": NAME} and nothing else");
    const std::string why = node_.Command(body["command"].get<std::string>());
    if (!why.empty()) {
      process_.log().Info("the page's " + body["command"].get<std::string>() + " refused: " + why);
      return reply(node_.CommandsRefused().empty() ? 400 : 403, why);
    }
    reply(200, "");
  });
}

}  // namespace ws::view
