#include "page_server.h"

#include <algorithm>
#include <fstream>
#include <optional>
#include <sstream>
#include <string_view>

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

PageServer::PageServer(Process& process, EventHub& hub, const BlobStore& blobs, Audience& audience, ViewNode& node,
                       const std::string& address, int port, const std::string& three_dir)
    : process_(process),
      hub_(hub),
      blobs_(blobs),
      audience_(audience),
      node_(node),
      assets_{{"/", {kIndexHtml, "text/html; charset=utf-8"}},
              {"/view.js", {kViewJs, "text/javascript"}},
              {"/view.css", {kViewCss, "text/css"}},
              {"/cloud3d.js", {kCloud3dJs, "text/javascript"}},
              {"/freshness.js", {kFreshnessJs, "text/javascript"}},
              {"/process_table.js", {kProcessTableJs, "text/javascript"}},
              {"/view_list.js", {kViewListJs, "text/javascript"}},
              {"/three.min.js", {ReadFile(three_dir + "/build/three.min.js"), "text/javascript"}},
              {"/OrbitControls.js",
               {ReadFile(three_dir + "/examples/js/controls/OrbitControls.js"), "text/javascript"}}} {
  HttpServer::Limits limits;
  limits.body = kMaxBody;
  server_ = std::make_unique<HttpServer>(
      address, port, [this](const HttpRequest& req, HttpResponse& res) { Handle(req, res); }, limits);
  process_.log().Info("the page: http://" + address + ":" + std::to_string(server_->port()) + "/");
}

PageServer::~PageServer() {
  hub_.Close();  // the streams end, so the server can join them
  server_.reset();
}

void PageServer::Handle(const HttpRequest& req, HttpResponse& res) {
  const HttpHead& head = req.head;
  if (head.method == "POST" && head.path == "/command") return Command(req, res);
  if (head.method != "GET") return res.Text(405, "GET, or POST /command");
  for (const auto& [path, asset] : assets_)
    if (head.path == path) return asset.Serve(head, res);
  // The id is at most 18 digits, so it always fits an int64.
  static constexpr std::string_view kBlob = "/blob/";
  if (const std::string_view id = std::string_view(head.path).substr(std::min(head.path.size(), kBlob.size()));
      head.path.compare(0, kBlob.size(), kBlob) == 0 && !id.empty() && id.size() <= 18 &&
      std::all_of(id.begin(), id.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return ServeBlob(std::string(id), res);
  if (head.path == "/events") return Events(head, res);
  res.Text(404, "not here: the page is /");
}

void PageServer::ServeBlob(const std::string& id, HttpResponse& res) {
  const auto blob = blobs_.Get(std::stoll(id));
  if (!blob) return res.Text(404, "no longer kept: the page shows the next one");
  res.fields.emplace_back("Cache-Control", "private, max-age=60, immutable");  // a blob never changes
  res.content_type = blob->content_type;
  res.shared_body = {reinterpret_cast<const char*>(blob->bytes.data()), blob->bytes.size()};
  res.owner = blob;
}

void PageServer::Events(const HttpHead& req, HttpResponse& res) {
  Audience::Views views;
  try {
    views = Audience::Parse(req.Param("view"));
  } catch (const std::invalid_argument& e) {
    return res.Text(400, e.what());
  }
  if (++streams_ > kMaxStreams) {
    --streams_;
    return res.Text(503, "too many pages open on this stereo-view");
  }
  res.content_type = "text/event-stream";
  res.fields.emplace_back("Cache-Control", "no-cache");
  audience_.Join(views);
  res.stream = [this, views](const HttpResponse::Write& write) {
    auto& browsers = process_.Counters(kBrowserCounters);
    EventHub::Cursor cursor;
    while (true) {
      int64_t skipped = 0;
      const auto events = hub_.Next(cursor, std::chrono::seconds(1), &skipped);
      browsers.skipped += skipped;
      if (hub_.closed()) break;
      std::string text = events.empty() ? ": still here\n\n" : "";
      for (const Event& event : events) text += "event: " + event.topic + "\ndata: " + *event.json + "\n\n";
      if (!write(text)) break;
      browsers.published += int64_t(events.size());
    }
    browsers.skipped += hub_.Unsent(cursor);
    audience_.Leave(views);
    --streams_;
  };
}

void PageServer::Command(const HttpRequest& req, HttpResponse& res) {
  auto reply = [&res](int status, const std::string& error) {
    res.Text(status, nlohmann::json{{"error", error}}.dump(), "application/json");
  };
  if (req.head.Field("x-widestereo-page") != "1")
    return reply(400, "a command comes from the page (header X-Widestereo-Page: 1)");
  // At most kMaxBody bytes (the server refused more), so at most that deep.
  const auto body = nlohmann::json::parse(req.body, nullptr, false);
  auto integer = [&body](const char* key) { return body.contains(key) && body[key].is_number_integer(); };
  const bool names_view = body.is_object() && integer("frame") && integer("utime") && body.size() == 3;
  if (!body.is_object() || !body.contains("command") || !body["command"].is_string() ||
      (body.size() != 1 && !names_view))
    return reply(400, "the body is {\"command\": NAME} and nothing else, or for remove "
                      "{\"command\": \"remove\", \"frame\": ID, \"utime\": US}");
  std::optional<std::pair<int64_t, int64_t>> view;
  if (names_view) view.emplace(body["frame"].get<int64_t>(), body["utime"].get<int64_t>());
  const std::string why = node_.Command(body["command"].get<std::string>(), view);
  if (!why.empty()) {
    process_.log().Info("the page's " + body["command"].get<std::string>() + " refused: " + why);
    return reply(node_.CommandsRefused().empty() ? 400 : 403, why);
  }
  reply(200, "");
}

}  // namespace ws::view
