#include "view/http_head.h"

#include <algorithm>
#include <cctype>

namespace ws::view {
namespace {

// RFC 9110 tchar: the characters of a method or a field name.
bool IsToken(std::string_view s) {
  static constexpr std::string_view kSpecials = "!#$%&'*+-.^_`|~";
  return !s.empty() && std::all_of(s.begin(), s.end(), [](unsigned char c) {
    return std::isalnum(c) || kSpecials.find(char(c)) != std::string_view::npos;
  });
}

bool IsVisible(std::string_view s) {
  return std::all_of(s.begin(), s.end(), [](unsigned char c) { return c > 0x20 && c < 0x7f; });
}

// A field value: visible characters, spaces, tabs and obs-text, no control.
bool IsFieldValue(std::string_view s) {
  return std::all_of(s.begin(), s.end(), [](unsigned char c) { return c == '\t' || (c >= 0x20 && c != 0x7f); });
}

std::string_view Trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

std::string Lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = char(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

int HexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  c = char(std::tolower(static_cast<unsigned char>(c)));
  return c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
}

std::string PercentDecode(std::string_view s) {
  std::string out;
  for (size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '+') {
      out += ' ';
    } else if (s[i] == '%' && i + 2 < s.size() && HexDigit(s[i + 1]) >= 0 && HexDigit(s[i + 2]) >= 0) {
      out += char(HexDigit(s[i + 1]) * 16 + HexDigit(s[i + 2]));
      i += 2;
    } else {
      out += s[i];
    }
  }
  return out;
}

HeadParse Refuse(int status, std::string why) {
  HeadParse parse;
  parse.state = HeadParse::State::kRefused;
  parse.status = status;
  parse.why = std::move(why);
  return parse;
}

// "METHOD /target HTTP/1.x" into `head`; "" or why not.
std::string ParseRequestLine(std::string_view line, HttpHead& head, int& status) {
  status = 400;
  const size_t sp1 = line.find(' '), sp2 = line.rfind(' ');
  if (sp1 == std::string_view::npos || sp2 == sp1) return "the request line is METHOD TARGET HTTP/1.1";
  const std::string_view method = line.substr(0, sp1), target = line.substr(sp1 + 1, sp2 - sp1 - 1),
                         version = line.substr(sp2 + 1);
  if (!IsToken(method)) return "the method is not a token";
  if (target.empty() || target[0] != '/' || !IsVisible(target)) return "the target is a path from /";
  if (version != "HTTP/1.1" && version != "HTTP/1.0") {
    status = version.substr(0, 5) == "HTTP/" ? 505 : 400;
    return "HTTP/1.1 only";
  }
  head.method = method;
  head.minor_version = version.back() - '0';
  const size_t question = target.find('?');
  head.path = target.substr(0, question);
  if (question != std::string_view::npos) head.query = target.substr(question + 1);
  return "";
}

}  // namespace

std::string HttpHead::Field(std::string_view name) const {
  for (const auto& [n, value] : fields)
    if (n == name) return value;
  return "";
}

bool HttpHead::Has(std::string_view name) const {
  return std::any_of(fields.begin(), fields.end(), [name](const auto& field) { return field.first == name; });
}

std::string HttpHead::Param(std::string_view name) const {
  std::string_view rest = query;
  while (!rest.empty()) {
    const size_t amp = rest.find('&');
    const std::string_view pair = rest.substr(0, amp);
    rest = amp == std::string_view::npos ? std::string_view() : rest.substr(amp + 1);
    const size_t eq = pair.find('=');
    if (PercentDecode(pair.substr(0, eq)) == name)
      return eq == std::string_view::npos ? "" : PercentDecode(pair.substr(eq + 1));
  }
  return "";
}

bool HttpHead::KeepAlive() const {
  const std::string connection = Lower(Field("connection"));
  return minor_version == 1 ? connection != "close" : connection == "keep-alive";
}

HeadParse ParseHead(std::string_view bytes) {
  bytes = bytes.substr(0, kMaxHead);
  const size_t line_end = bytes.find("\r\n");
  if (line_end == std::string_view::npos ? bytes.size() > kMaxRequestLine + 1 : line_end > kMaxRequestLine)
    return Refuse(414, "the request line is longer than " + std::to_string(kMaxRequestLine) + " bytes");
  const size_t end = bytes.find("\r\n\r\n");
  if (end == std::string_view::npos)
    return bytes.size() == kMaxHead ? Refuse(431, "the head is longer than " + std::to_string(kMaxHead) + " bytes")
                                    : HeadParse();
  HeadParse parse;
  int status = 400;
  if (std::string why = ParseRequestLine(bytes.substr(0, line_end), parse.head, status); !why.empty())
    return Refuse(status, why);
  std::string_view rest = bytes.substr(line_end + 2, end + 2 - (line_end + 2));  // each field with its CRLF
  while (!rest.empty()) {
    const size_t eol = rest.find("\r\n");
    const std::string_view line = rest.substr(0, eol);
    rest.remove_prefix(eol + 2);
    const size_t colon = line.find(':');
    if (colon == std::string_view::npos || !IsToken(line.substr(0, colon)))
      return Refuse(400, "a header field is NAME: VALUE");  // also a folded line, which starts with a space
    const std::string_view value = Trim(line.substr(colon + 1));
    if (!IsFieldValue(value)) return Refuse(400, "a header field's value has a control character");
    if (parse.head.fields.size() == kMaxHeaderFields)
      return Refuse(431, "more than " + std::to_string(kMaxHeaderFields) + " header fields");
    parse.head.fields.emplace_back(Lower(line.substr(0, colon)), std::string(value));
  }
  const auto count = [&](std::string_view name) {
    return std::count_if(parse.head.fields.begin(), parse.head.fields.end(),
                         [name](const auto& field) { return field.first == name; });
  };
  if (count("host") > 1 || (parse.head.minor_version == 1 && count("host") == 0))
    return Refuse(400, "an HTTP/1.1 request has exactly one Host");
  if (parse.head.Has("transfer-encoding")) return Refuse(501, "no Transfer-Encoding: a body has a Content-Length");
  if (count("content-length") > 1) return Refuse(400, "more than one Content-Length");
  const std::string length = parse.head.Field("content-length");
  if (length.size() > 18 || !std::all_of(length.begin(), length.end(), [](char c) { return c >= '0' && c <= '9'; }) ||
      (parse.head.Has("content-length") && length.empty()))
    return Refuse(400, "the Content-Length is a number of bytes");
  parse.head.content_length = length.empty() ? 0 : std::stoll(length);
  parse.state = HeadParse::State::kDone;
  parse.length = end + 4;
  return parse;
}

}  // namespace ws::view
