#include "runtime/opencv_yaml.h"

#include <fstream>
#include <iterator>
#include <sstream>

namespace ws {

void CheckOpenCvYamlLayout(const std::string& text) {
  std::istringstream lines(text);
  std::string line;
  int number = 0, top_line = 0;
  size_t top_indent = std::string::npos;  // of the first line of the top-level collection
  while (std::getline(lines, line)) {
    ++number;
    const size_t indent = line.find_first_not_of(' ');
    if (indent == std::string::npos || line[indent] == '#') continue;
    const std::string where = "line " + std::to_string(number) + ": ";
    if (line.compare(indent, 3, "...") == 0)
      throw YamlFileError(where + "'...' (the end of a YAML document) is not supported");
    if (top_indent == std::string::npos) {
      // Directives and the document start come before the top-level collection.
      if (line[indent] != '%' && line.compare(indent, 3, "---") != 0) {
        top_indent = indent;
        top_line = number;
      }
    } else if (indent < top_indent) {
      throw YamlFileError(where + "indented less than line " + std::to_string(top_line) +
                          ", where the top level starts");
    }
  }
}

void OpenOpenCvYaml(cv::FileStorage& storage, const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw YamlFileError("cannot open the file");
  const std::string text{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
  if (file.bad()) throw YamlFileError("cannot read the file");
  CheckOpenCvYamlLayout(text);
  try {
    storage.open(text, cv::FileStorage::READ | cv::FileStorage::MEMORY | cv::FileStorage::FORMAT_YAML);
  } catch (const cv::Exception& e) {
    throw YamlFileError("not YAML that OpenCV reads (the first line must be '%YAML:1.0'): " + e.err);
  }
}

}  // namespace ws
