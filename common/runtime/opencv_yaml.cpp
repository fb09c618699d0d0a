#include "runtime/opencv_yaml.h"

#include <algorithm>
#include <sstream>

#include "runtime/bounded_file.h"

namespace ws {
namespace {

// Adds the flow collections the line opens (and takes those it closes) to
// `flow_depth`; returns the deepest nesting within the line, counting its
// block sequence entries ("- ") too. Quoted text and comments do not count.
int LineNesting(const std::string& line, int* flow_depth) {
  int deepest = *flow_depth, dashes = 0;
  char quote = 0;
  for (size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quote) {
      if (quote == '"' && c == '\\') ++i;
      else if (c == quote) quote = 0;
      continue;
    }
    if (c == '\'' || c == '"') quote = c;
    else if (c == '#' && (i == 0 || line[i - 1] == ' ')) break;
    else if (c == '[' || c == '{') ++*flow_depth;
    else if (c == ']' || c == '}') *flow_depth = std::max(0, *flow_depth - 1);
    else if (c == '-' && (i + 1 == line.size() || line[i + 1] == ' ')) ++dashes;
    deepest = std::max(deepest, *flow_depth + dashes);
  }
  return deepest;
}

}  // namespace

void CheckOpenCvYamlLayout(const std::string& text) {
  std::istringstream lines(text);
  std::string line;
  int number = 0, top_line = 0;
  size_t top_indent = std::string::npos;  // of the first line of the top-level collection
  int flow_depth = 0;
  while (std::getline(lines, line)) {
    ++number;
    const size_t indent = line.find_first_not_of(' ');
    if (indent == std::string::npos || line[indent] == '#') continue;
    const std::string where = "line " + std::to_string(number) + ": ";
    if (LineNesting(line, &flow_depth) > kMaxYamlNesting)
      throw YamlFileError(where + "nested more than " + std::to_string(kMaxYamlNesting) + " deep");
    if (line.compare(indent, 3, "...") == 0)
      throw YamlFileError(where + "'...' (the end of a YAML document) is not supported");
    if (top_indent == std::string::npos) {
      // Directives and the document start come before the top-level collection.
      if (line.compare(indent, 3, "---") == 0) {
        const size_t rest = line.find_first_not_of(' ', indent + 3);
        if (rest != std::string::npos && line[rest] != '#')
          throw YamlFileError(where + "nothing may follow '---' on its line");
      } else if (line[indent] != '%') {
        top_indent = indent;
        top_line = number;
      }
    } else if (indent < top_indent) {
      throw YamlFileError(where + "indented less than line " + std::to_string(top_line) +
                          ", where the top level starts");
    }
  }
}

void OpenOpenCvYaml(cv::FileStorage& storage, const std::string& path, size_t max_bytes) {
  std::string text;
  try {
    text = ReadBoundedFile(path, max_bytes);
  } catch (const BoundedFileError& e) {
    throw YamlFileError(e.what());
  }
  CheckOpenCvYamlLayout(text);
  try {
    storage.open(text, cv::FileStorage::READ | cv::FileStorage::MEMORY | cv::FileStorage::FORMAT_YAML);
  } catch (const cv::Exception& e) {
    throw YamlFileError(text.rfind("%YAML:1.0", 0) == 0
                            ? "does not parse as YAML (OpenCV: " + e.err + ")"
                            : "not YAML that OpenCV reads (the first line must be '%YAML:1.0'): " + e.err);
  } catch (const std::exception& e) {  // OpenCV lets some through, e.g. std::length_error
    throw YamlFileError(std::string("not YAML that OpenCV reads: ") + e.what());
  }
}

}  // namespace ws
