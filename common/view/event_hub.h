// What the page shows, for every browser at once: per topic ("frame",
// "coverage", "cloud", ...) the newest event, a JSON text. Each browser's
// stream (a Cursor) sends every topic's newest version it has not sent yet;
// a version replaced before the stream sent it is skipped for that browser
// and counted. Publish never waits for a browser: a slow or closed one only
// misses versions (newest wins), the bus side goes on at its own rate.
//
// A topic may also carry each version's change from the one before (a
// delta: what a long list gained and lost): a stream that sent the version
// before gets the delta, any other (a new or reconnected browser, one that
// missed a version) the whole event, so a browser's copy is always whole
// and an update costs what changed.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace ws::view {

struct Event {
  std::string topic;
  std::shared_ptr<const std::string> json;
};

class EventHub {
 public:
  // One browser's stream: the version of each topic it has sent.
  struct Cursor {
    std::map<std::string, int64_t> sent;
  };

  // Replaces the topic's event and wakes every stream. `delta` ("": none)
  // is the change from the topic's previous version, sent instead of `json`
  // to a stream that sent that version.
  void Publish(const std::string& topic, std::string json, std::string delta = "");
  // Waits up to `timeout` for a topic newer than `cursor` has sent, then
  // returns every such topic's newest event (none: timed out, or Close()d)
  // and marks them sent. Versions the cursor never saw (published between
  // two of its sends) are added to *skipped.
  std::vector<Event> Next(Cursor& cursor, std::chrono::milliseconds timeout, int64_t* skipped);
  // The versions published since `cursor` last sent each topic: what a
  // stream that ends now has missed.
  int64_t Unsent(const Cursor& cursor) const;
  // Wakes every stream for good: Next returns at once from then on.
  void Close();
  bool closed() const;

 private:
  struct Topic {
    int64_t version = 0;  // publishes so far
    std::shared_ptr<const std::string> json;
    std::shared_ptr<const std::string> delta;  // null: none
  };
  bool HasNews(const Cursor& cursor) const;

  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::map<std::string, Topic> topics_;
  bool closed_ = false;
};

}  // namespace ws::view
