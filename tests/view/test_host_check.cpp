// The names the page is served by: the loopback names and the connection's
// own address, any port; any other is a page of another site (DNS
// rebinding), refused. An Origin is the page's own site or none.
#include <gtest/gtest.h>

#include "view/host_check.h"

namespace {

using ws::view::HostAllowed;
using ws::view::OriginAllowed;

TEST(HostCheck, LoopbackNamesAndTheOwnAddressWithAnyPort) {
  for (const char* host : {"localhost:8077", "LOCALHOST:8077", "127.0.0.1:8077", "[::1]:8077", "10.0.0.7:8077",
                           "localhost", "[::1]", "10.0.0.7", "localhost:9000"})
    EXPECT_TRUE(HostAllowed(host, "10.0.0.7")) << host;
  EXPECT_TRUE(HostAllowed("[fe80::1]:8077", "fe80::1"));
  for (const char* host : {"rebind.example:8077", "rebind.example", "10.0.0.8:8077", "localhost.rebind.example:8077",
                           "", ":8077", "localhost:", "localhost:80a", "localhost:8077:8077", "robot.local:8077",
                           "[::1]x:8077", "127.0.0.1.rebind.example"})
    EXPECT_FALSE(HostAllowed(host, "10.0.0.7")) << host;
}

TEST(HostCheck, AnOriginIsThePagesOwnSiteOrNone) {
  EXPECT_TRUE(OriginAllowed("", "localhost:8077"));
  EXPECT_TRUE(OriginAllowed("http://localhost:8077", "localhost:8077"));
  EXPECT_TRUE(OriginAllowed("http://127.0.0.1:9000", "127.0.0.1:9000"));  // through a tunnel
  for (const char* origin : {"null", "http://rebind.example:8077", "https://localhost:8077", "localhost:8077",
                             "http://localhost:8077/", "http://127.0.0.1:8077", "http://localhost:3000"})
    EXPECT_FALSE(OriginAllowed(origin, "localhost:8077")) << origin;
}

}  // namespace
