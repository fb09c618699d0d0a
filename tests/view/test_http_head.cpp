// The page server's request heads: parsed from what has come so far, the
// limits refused as soon as they are passed (not once the head ends).
#include <gtest/gtest.h>

#include <string>

#include "view/http_head.h"

namespace {

using ws::view::HeadParse;
using ws::view::kMaxHead;
using ws::view::kMaxHeaderFields;
using ws::view::kMaxRequestLine;
using ws::view::ParseHead;
using State = HeadParse::State;

TEST(HttpHead, ACompleteHeadGivesItsFieldsAndLength) {
  const std::string head =
      "GET /events?view=depth&x=a%20b+c HTTP/1.1\r\nHost: localhost:8077\r\nAccept-Encoding:  gzip, br \r\n\r\n";
  const HeadParse parse = ParseHead(head + "next");
  ASSERT_EQ(parse.state, State::kDone) << parse.why;
  EXPECT_EQ(parse.length, head.size());
  EXPECT_EQ(parse.head.method, "GET");
  EXPECT_EQ(parse.head.path, "/events");
  EXPECT_EQ(parse.head.Param("view"), "depth");
  EXPECT_EQ(parse.head.Param("x"), "a b c");
  EXPECT_EQ(parse.head.Param("none"), "");
  EXPECT_EQ(parse.head.Field("host"), "localhost:8077");
  EXPECT_EQ(parse.head.Field("accept-encoding"), "gzip, br");
  EXPECT_TRUE(parse.head.KeepAlive());
  EXPECT_EQ(parse.head.content_length, 0);
}

TEST(HttpHead, EveryPrefixOfAHeadIsIncomplete) {
  const std::string head = "POST /command HTTP/1.1\r\nHost: a\r\nContent-Length: 19\r\n\r\n";
  for (size_t n = 0; n < head.size(); ++n) EXPECT_EQ(ParseHead(head.substr(0, n)).state, State::kIncomplete) << n;
  const HeadParse parse = ParseHead(head);
  ASSERT_EQ(parse.state, State::kDone);
  EXPECT_EQ(parse.head.content_length, 19);
}

TEST(HttpHead, AnUnterminatedRequestLineIsRefusedAtItsLimit) {
  const std::string line = "GET /" + std::string(kMaxRequestLine, 'a');
  EXPECT_EQ(ParseHead(line.substr(0, kMaxRequestLine)).state, State::kIncomplete);
  const HeadParse parse = ParseHead(line);
  EXPECT_EQ(parse.state, State::kRefused);
  EXPECT_EQ(parse.status, 414);
}

TEST(HttpHead, HeadersPastTheirLimitsAreRefused) {
  std::string head = "GET / HTTP/1.1\r\nHost: a\r\n";
  while (head.size() < kMaxHead) head += "X-Long: " + std::string(100, 'b') + "\r\n";
  EXPECT_EQ(ParseHead(head).status, 431);  // no end yet, and no room for one

  std::string many = "GET / HTTP/1.1\r\nHost: a\r\n";
  for (size_t i = 0; i < kMaxHeaderFields; ++i) many += "X: 1\r\n";
  EXPECT_EQ(ParseHead(many + "\r\n").status, 431);
}

TEST(HttpHead, MalformedHeadsAreRefused) {
  const auto status = [](const std::string& head) {
    const HeadParse parse = ParseHead(head);
    EXPECT_EQ(parse.state, State::kRefused) << head;
    return parse.status;
  };
  EXPECT_EQ(status("GET / HTTP/2.0\r\nHost: a\r\n\r\n"), 505);
  EXPECT_EQ(status("GET / SPDY\r\nHost: a\r\n\r\n"), 400);
  EXPECT_EQ(status("GET http://a/ HTTP/1.1\r\nHost: a\r\n\r\n"), 400);
  EXPECT_EQ(status("GET / HTTP/1.1\r\n\r\n"), 400);                        // no Host
  EXPECT_EQ(status("GET / HTTP/1.1\r\nHost: a\r\nHost: b\r\n\r\n"), 400);  // two
  EXPECT_EQ(status("GET / HTTP/1.1\r\nHost: a\r\n folded\r\n\r\n"), 400);
  EXPECT_EQ(status(std::string("GET / HTTP/1.1\r\nHost: a\0b\r\n\r\n", 29)), 400);
  EXPECT_EQ(status("POST / HTTP/1.1\r\nHost: a\r\nContent-Length: -1\r\n\r\n"), 400);
  EXPECT_EQ(status("POST / HTTP/1.1\r\nHost: a\r\nContent-Length: 1\r\nContent-Length: 1\r\n\r\n"), 400);
  EXPECT_EQ(status("POST / HTTP/1.1\r\nHost: a\r\nContent-Length: 9999999999999999999\r\n\r\n"), 400);
  EXPECT_EQ(status("POST / HTTP/1.1\r\nHost: a\r\nTransfer-Encoding: chunked\r\n\r\n"), 501);
}

TEST(HttpHead, HttpOneZeroNeedsNoHostAndClosesUnlessAsked) {
  HeadParse parse = ParseHead("GET / HTTP/1.0\r\n\r\n");
  ASSERT_EQ(parse.state, State::kDone);
  EXPECT_FALSE(parse.head.KeepAlive());
  parse = ParseHead("GET / HTTP/1.0\r\nConnection: Keep-Alive\r\n\r\n");
  EXPECT_TRUE(parse.head.KeepAlive());
  parse = ParseHead("GET / HTTP/1.1\r\nHost: a\r\nConnection: close\r\n\r\n");
  EXPECT_FALSE(parse.head.KeepAlive());
}

}  // namespace
