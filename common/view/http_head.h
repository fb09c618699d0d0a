// The head of an HTTP/1.1 request (request line and header fields, RFC 9112)
// as stereo-view's page server reads it from a socket: parsed from the bytes
// received so far, with hard limits checked on every call, so that a head
// never grows a buffer past them. A head that is not complete yet and already
// over a limit is refused at once (414 for the request line, 431 for the
// header fields), not after more bytes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace ws::view {

inline constexpr size_t kMaxRequestLine = 4096;  // "GET /events?view=calibration HTTP/1.1" is 38
inline constexpr size_t kMaxHead = 16384;        // request line and every header field
inline constexpr size_t kMaxHeaderFields = 64;

struct HttpHead {
  std::string method, path, query;  // target "/p?q": path "/p", query "q"
  int minor_version = 1;            // HTTP/1.minor
  int64_t content_length = 0;       // bytes of the body (no Transfer-Encoding is taken)
  std::vector<std::pair<std::string, std::string>> fields;  // names lower case, values trimmed

  // The value of the field `name` (lower case), "" when absent.
  std::string Field(std::string_view name) const;
  // Whether the field `name` is present (even empty).
  bool Has(std::string_view name) const;
  // The query parameter `name`, percent-decoded ('+' as a space), "" when absent.
  std::string Param(std::string_view name) const;
  // Whether the connection stays open after the response (HTTP/1.1 unless
  // "Connection: close"; HTTP/1.0 only with "Connection: keep-alive").
  bool KeepAlive() const;
};

struct HeadParse {
  enum class State { kIncomplete, kDone, kRefused };
  State state = State::kIncomplete;
  size_t length = 0;  // kDone: bytes of `bytes` the head took (with its blank line)
  int status = 0;     // kRefused: 400, 414, 431, 501 or 505
  std::string why;    // kRefused: for the body of the reply
  HttpHead head;      // kDone
};

// Parses the head at the start of `bytes` (all that was received so far).
// Never reads past kMaxHead bytes of it.
HeadParse ParseHead(std::string_view bytes);

}  // namespace ws::view
