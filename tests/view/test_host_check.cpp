// The names the page is served by: the loopback names and the connection's
// own address, each with the server's port; any other is a page of another
// site (DNS rebinding), refused.
#include <gtest/gtest.h>

#include "view/host_check.h"

namespace {

using ws::view::HostAllowed;
using ws::view::OriginAllowed;

TEST(HostCheck, LoopbackNamesAndTheOwnAddressWithThePort) {
  for (const char* host : {"localhost:8077", "LOCALHOST:8077", "127.0.0.1:8077", "[::1]:8077", "10.0.0.7:8077"})
    EXPECT_TRUE(HostAllowed(host, "10.0.0.7", 8077)) << host;
  EXPECT_TRUE(HostAllowed("[fe80::1]:8077", "fe80::1", 8077));
  for (const char* host : {"evil.example:8077", "localhost", "localhost:8078", "127.0.0.1:80", "10.0.0.8:8077",
                           "localhost.evil.example:8077", "", ":8077", "localhost:8077:8077", "robot.local:8077"})
    EXPECT_FALSE(HostAllowed(host, "10.0.0.7", 8077)) << host;
}

TEST(HostCheck, OnPort80TheNameAloneToo) {
  EXPECT_TRUE(HostAllowed("localhost", "127.0.0.1", 80));
  EXPECT_TRUE(HostAllowed("localhost:80", "127.0.0.1", 80));
  EXPECT_FALSE(HostAllowed("evil.example", "127.0.0.1", 80));
}

TEST(HostCheck, OriginIsAbsentOrAnAllowedHostOverHttp) {
  EXPECT_TRUE(OriginAllowed("", "127.0.0.1", 8077));
  EXPECT_TRUE(OriginAllowed("http://localhost:8077", "127.0.0.1", 8077));
  EXPECT_TRUE(OriginAllowed("http://127.0.0.1:8077", "127.0.0.1", 8077));
  for (const char* origin : {"null", "http://evil.example:8077", "https://localhost:8077", "localhost:8077",
                             "http://localhost:8077/"})
    EXPECT_FALSE(OriginAllowed(origin, "127.0.0.1", 8077)) << origin;
}

}  // namespace
