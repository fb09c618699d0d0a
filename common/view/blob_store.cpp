#include "view/blob_store.h"

#include <algorithm>

namespace ws::view {

std::string BlobStore::Put(const std::string& topic, size_t keep, Blob blob) {
  auto kept = std::make_shared<const Blob>(std::move(blob));
  std::lock_guard<std::mutex> lock(mutex_);
  const int64_t id = next_id_++;
  blobs_.emplace(id, std::move(kept));
  std::deque<int64_t>& ids = topics_[topic];
  ids.push_back(id);
  while (ids.size() > std::max<size_t>(1, keep)) {
    blobs_.erase(ids.front());
    ids.pop_front();
  }
  return "blob/" + std::to_string(id);
}

std::shared_ptr<const Blob> BlobStore::Get(int64_t id) const {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto found = blobs_.find(id);
  return found == blobs_.end() ? nullptr : found->second;
}

}  // namespace ws::view
