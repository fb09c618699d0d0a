// The page's binary payloads (JPEG images, point arrays), kept apart from its
// JSON events so that they cross HTTP as they are: an event names a payload
// by its path ("blob/17"), and the browser fetches it from stereo-view
// (processes/stereo-view/page_server.cpp) only when it draws it. Each payload
// gets the next id and never changes; per topic ("frame", "cloud", ...) the
// store keeps the newest few, as many as the caller says, and forgets older
// ones (a page that asks for one gets 404 and waits for the next event).
// Thread-safe.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace ws::view {

struct Blob {
  std::string content_type;  // "image/jpeg", "application/octet-stream"
  std::vector<uint8_t> bytes;
};

class BlobStore {
 public:
  // Keeps `blob`, and the newest `keep` of `topic` (at least this one);
  // returns the path the page fetches it at: "blob/ID".
  std::string Put(const std::string& topic, size_t keep, Blob blob);
  // The blob of `id` (the digits after "blob/"), or null when it was never
  // stored or has been forgotten.
  std::shared_ptr<const Blob> Get(int64_t id) const;

 private:
  mutable std::mutex mutex_;
  int64_t next_id_ = 1;
  std::map<int64_t, std::shared_ptr<const Blob>> blobs_;
  std::map<std::string, std::deque<int64_t>> topics_;  // each topic's ids kept, oldest first
};

}  // namespace ws::view
