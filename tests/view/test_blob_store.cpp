// The page's payloads: each stored once under a new path, the newest of each
// topic kept, the oldest forgotten (404 for the page), never an id reused.
#include <gtest/gtest.h>

#include <string>

#include "view/blob_store.h"

namespace {

using ws::view::Blob;
using ws::view::BlobStore;

int64_t IdOf(const std::string& path) {
  EXPECT_EQ(path.rfind("blob/", 0), 0u) << path;
  return std::stoll(path.substr(5));
}

TEST(BlobStore, KeepsTheNewestOfEachTopicAndForgetsTheOldest) {
  BlobStore store;
  const int64_t a = IdOf(store.Put("frame", 2, {"image/jpeg", {1, 2, 3}}));
  const int64_t b = IdOf(store.Put("frame", 2, {"image/jpeg", {4}}));
  const int64_t cloud = IdOf(store.Put("cloud", 1, {"application/octet-stream", {9}}));
  EXPECT_NE(a, b);
  ASSERT_TRUE(store.Get(a));
  EXPECT_EQ(store.Get(a)->bytes, (std::vector<uint8_t>{1, 2, 3}));
  EXPECT_EQ(store.Get(cloud)->content_type, "application/octet-stream");
  const int64_t c = IdOf(store.Put("frame", 2, {"image/jpeg", {5}}));
  EXPECT_FALSE(store.Get(a)) << "the topic's oldest is forgotten beyond what it keeps";
  EXPECT_TRUE(store.Get(b));
  EXPECT_TRUE(store.Get(cloud)) << "another topic's are not";
  EXPECT_EQ(store.Get(c)->bytes, (std::vector<uint8_t>{5}));
  const int64_t cloud2 = IdOf(store.Put("cloud", 0, {"application/octet-stream", {8}}));
  EXPECT_FALSE(store.Get(cloud));
  EXPECT_TRUE(store.Get(cloud2)) << "the newest is always kept";
  EXPECT_FALSE(store.Get(cloud2 + 1)) << "an id never given";
  EXPECT_FALSE(store.Get(-1));
}

}  // namespace
