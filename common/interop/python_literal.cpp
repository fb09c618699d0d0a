#include "interop/python_literal.h"

#include <cctype>
#include <cstdlib>
#include <stdexcept>

namespace ws {
namespace {

class Parser {
 public:
  explicit Parser(const std::string& text) : s_(text) {}

  PyLiteral Document() {
    PyLiteral value = Value(0);
    Skip();
    if (at_ != s_.size()) Fail("text after the literal");
    return value;
  }

 private:
  [[noreturn]] void Fail(const std::string& what) const {
    int line = 1;
    for (size_t i = 0; i < at_ && i < s_.size(); ++i) line += s_[i] == '\n';
    throw std::invalid_argument("line " + std::to_string(line) + ": " + what);
  }
  // Past blank space and comments.
  void Skip() {
    while (at_ < s_.size()) {
      if (std::isspace(static_cast<unsigned char>(s_[at_]))) {
        ++at_;
      } else if (s_[at_] == '#') {
        while (at_ < s_.size() && s_[at_] != '\n') ++at_;
      } else {
        break;
      }
    }
  }
  bool Accept(char c) {
    Skip();
    if (at_ < s_.size() && s_[at_] == c) {
      ++at_;
      return true;
    }
    return false;
  }
  bool Word(const std::string& word) {
    if (s_.compare(at_, word.size(), word) != 0) return false;
    at_ += word.size();
    return true;
  }

  PyLiteral Value(int depth) {
    if (depth > 32) Fail("nested too deeply");
    Skip();
    if (at_ >= s_.size()) Fail("a value expected, the text ended");
    const char c = s_[at_];
    PyLiteral v;
    if (c == '{' || c == '[' || c == '(') {
      ++at_;
      const bool dict = c == '{';
      const char close = dict ? '}' : c == '[' ? ']' : ')';
      v.kind = dict ? PyLiteral::Kind::kDict : PyLiteral::Kind::kList;
      while (!Accept(close)) {
        if (dict) {
          const PyLiteral key = Value(depth + 1);
          if (key.kind != PyLiteral::Kind::kString) Fail("a dict key that is not a string");
          if (!Accept(':')) Fail("':' expected after a dict key");
          v.entries[key.text] = Value(depth + 1);
        } else {
          v.items.push_back(Value(depth + 1));
        }
        if (!Accept(',')) {
          if (!Accept(close)) Fail(std::string("',' or '") + close + "' expected");
          break;
        }
      }
    } else if (c == '\'' || c == '"' || (c == 'b' && at_ + 1 < s_.size() &&
                                         (s_[at_ + 1] == '\'' || s_[at_ + 1] == '"'))) {
      if (c == 'b') ++at_;
      v.kind = PyLiteral::Kind::kString;
      v.text = String();
    } else if (Word("True")) {
      v.kind = PyLiteral::Kind::kBool;
      v.number = 1;
    } else if (Word("False")) {
      v.kind = PyLiteral::Kind::kBool;
    } else if (Word("None")) {
      v.kind = PyLiteral::Kind::kNone;
    } else {
      const char* begin = s_.c_str() + at_;
      char* end = nullptr;
      v.number = std::strtod(begin, &end);
      if (end == begin) Fail(std::string("unexpected '") + c + "'");
      v.kind = PyLiteral::Kind::kNumber;
      at_ += end - begin;
    }
    return v;
  }

  // A quoted string without escapes other than \\, \' and \".
  std::string String() {
    const char quote = s_[at_++];
    std::string out;
    while (at_ < s_.size() && s_[at_] != quote) {
      if (s_[at_] == '\\') {
        if (++at_ >= s_.size()) break;
        if (s_[at_] != '\\' && s_[at_] != '\'' && s_[at_] != '"') Fail("an escape other than \\\\, \\' or \\\"");
      }
      out += s_[at_++];
    }
    if (at_ >= s_.size()) Fail("a string that does not end");
    ++at_;
    return out;
  }

  const std::string& s_;
  size_t at_ = 0;
};

}  // namespace

PyLiteral ParsePyLiteral(const std::string& text) { return Parser(text).Document(); }

}  // namespace ws
