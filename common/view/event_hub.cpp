#include "view/event_hub.h"

namespace ws::view {

void EventHub::Publish(const std::string& topic, std::string json, std::string delta) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    Topic& t = topics_[topic];
    ++t.version;
    t.json = std::make_shared<const std::string>(std::move(json));
    t.delta = delta.empty() ? nullptr : std::make_shared<const std::string>(std::move(delta));
  }
  changed_.notify_all();
}

bool EventHub::HasNews(const Cursor& cursor) const {
  for (const auto& [name, topic] : topics_) {
    const auto sent = cursor.sent.find(name);
    if (sent == cursor.sent.end() || sent->second < topic.version) return true;
  }
  return false;
}

std::vector<Event> EventHub::Next(Cursor& cursor, std::chrono::milliseconds timeout, int64_t* skipped) {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait_for(lock, timeout, [&] { return closed_ || HasNews(cursor); });
  std::vector<Event> events;
  if (closed_) return events;
  for (const auto& [name, topic] : topics_) {
    const auto sent = cursor.sent.find(name);
    if (sent != cursor.sent.end() && sent->second >= topic.version) continue;
    // A stream's first version of a topic is the newest: those before it were
    // published before the browser came, not skipped.
    const bool follows = sent != cursor.sent.end() && sent->second == topic.version - 1;
    if (sent != cursor.sent.end()) *skipped += topic.version - sent->second - 1;
    cursor.sent[name] = topic.version;
    events.push_back({name, follows && topic.delta ? topic.delta : topic.json});
  }
  return events;
}

int64_t EventHub::Unsent(const Cursor& cursor) const {
  std::lock_guard<std::mutex> lock(mutex_);
  int64_t unsent = 0;
  for (const auto& [name, sent] : cursor.sent) unsent += topics_.at(name).version - sent;
  return unsent;
}

void EventHub::Close() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    closed_ = true;
  }
  changed_.notify_all();
}

bool EventHub::closed() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return closed_;
}

}  // namespace ws::view
