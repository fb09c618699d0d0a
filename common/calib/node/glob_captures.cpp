#include "calib/node/glob_captures.h"

#include <stdexcept>

namespace ws::calib {
namespace {

// Index just past the bracket expression starting at glob[i] == '['.
size_t BracketEnd(const std::string& glob, size_t i) {
  size_t j = i + 1;
  if (j < glob.size() && glob[j] == '!') ++j;
  if (j < glob.size() && glob[j] == ']') ++j;  // a leading ']' is a member
  while (j < glob.size() && glob[j] != ']') ++j;
  if (j >= glob.size()) throw std::invalid_argument("glob '" + glob + "': '[' without ']'");
  return j + 1;
}

// Whether c is in the bracket expression glob[begin, end) ("[...]").
bool InBracket(const std::string& glob, size_t begin, size_t end, char c) {
  size_t j = begin + 1;
  const bool negate = glob[j] == '!';
  if (negate) ++j;
  const size_t close = end - 1;
  bool found = false;
  for (; j < close; ++j) {
    if (j + 2 < close && glob[j + 1] == '-') {  // a range a-z
      found = found || (glob[j] <= c && c <= glob[j + 2]);
      j += 2;
    } else {
      found = found || glob[j] == c;
    }
  }
  return found != negate;
}

// Matches glob[g..] against name[n..]; on success appends the `*` captures.
bool Match(const std::string& glob, size_t g, const std::string& name, size_t n,
           std::vector<std::string>* captures) {
  while (g < glob.size()) {
    const char c = glob[g];
    if (c == '*') {
      for (size_t length = 0; n + length <= name.size(); ++length) {
        std::vector<std::string> rest;
        if (Match(glob, g + 1, name, n + length, &rest)) {
          captures->push_back(name.substr(n, length));
          captures->insert(captures->end(), rest.begin(), rest.end());
          return true;
        }
      }
      return false;
    }
    if (n >= name.size()) return false;
    if (c == '?') {
      ++g;
    } else if (c == '[') {
      const size_t end = BracketEnd(glob, g);
      if (!InBracket(glob, g, end, name[n])) return false;
      g = end;
    } else {
      const char literal = c == '\\' && g + 1 < glob.size() ? glob[++g] : c;
      if (literal != name[n]) return false;
      ++g;
    }
    ++n;
  }
  return n == name.size();
}

}  // namespace

std::optional<std::vector<std::string>> GlobCaptures(const std::string& glob, const std::string& name) {
  GlobStars(glob);  // validates the brackets
  std::vector<std::string> captures;
  if (Match(glob, 0, name, 0, &captures)) return captures;
  if (!glob.empty() && glob[0] == '/') return std::nullopt;
  for (size_t slash = name.find('/'); slash != std::string::npos; slash = name.find('/', slash + 1)) {
    captures.clear();
    if (Match(glob, 0, name, slash + 1, &captures)) return captures;
  }
  return std::nullopt;
}

int GlobStars(const std::string& glob) {
  int stars = 0;
  for (size_t i = 0; i < glob.size(); ++i) {
    if (glob[i] == '\\') ++i;
    else if (glob[i] == '[') i = BracketEnd(glob, i) - 1;
    else if (glob[i] == '*') ++stars;
  }
  return stars;
}

}  // namespace ws::calib
