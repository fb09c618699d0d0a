// The subset of Python literals that mrcal's .cameramodel files are written
// in (mrcal's cameramodel.write; Python's ast.literal_eval reads them):
// dicts, lists and tuples, strings and bytes ('...', "...", b'...'),
// numbers, True, False, None, # comments and trailing commas.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace ws {

struct PyLiteral {
  enum class Kind { kNone, kBool, kNumber, kString, kList, kDict };
  Kind kind = Kind::kNone;
  double number = 0;  // kNumber, kBool (0 or 1)
  std::string text;   // kString (bytes too)
  std::vector<PyLiteral> items;               // kList
  std::map<std::string, PyLiteral> entries;   // kDict (string keys only)
};

// Parses one literal filling the whole text (comments and blank space
// around it allowed). Throws std::invalid_argument saying what is wrong and
// at which line. Nesting deeper than 32 is refused.
PyLiteral ParsePyLiteral(const std::string& text);

}  // namespace ws
