// Opening a YAML file with cv::FileStorage without hanging. OpenCV 4.6's YAML
// parser loops forever when its top-level collection ends before the end of
// the file and the text three characters on is a '-': after a line indented
// less than the first one ("%YAML:1.0\n  a: 1\nxyz-\n") or after a "..." line
// ("%YAML:1.0\na: 1\n...\n-\n"). It recurses once per level of nesting and
// overflows the stack at some 50000 levels ("[[[[..." or "- - - -..." on one
// line). Such files are rejected before OpenCV parses them.
#pragma once

#include <stdexcept>
#include <string>

#include <opencv2/core.hpp>

namespace ws {

// The file cannot be read, is laid out as above, or OpenCV does not parse it.
// The message says why, with the line where there is one, but not the path:
// loaders add it with their own error type.
struct YamlFileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Throws YamlFileError "line N: REASON" for a "..." line, text after "---"
// on its line, a line (other than a comment or blank) indented less than the
// first, or collections nested
// more than kMaxYamlNesting deep in flow style ([ {) or within one line (- - -).
constexpr int kMaxYamlNesting = 64;
void CheckOpenCvYamlLayout(const std::string& text);

// Reads `path`, checks it (CheckOpenCvYamlLayout) and opens it in `storage`
// for reading as YAML. Throws YamlFileError, also for a file of more than
// max_bytes: OpenCV's parse of it cannot be stopped (SIGTERM waits for it),
// and takes seconds and gigabytes for hundreds of megabytes.
constexpr size_t kMaxYamlFileBytes = size_t(64) << 20;
void OpenOpenCvYaml(cv::FileStorage& storage, const std::string& path, size_t max_bytes = kMaxYamlFileBytes);

}  // namespace ws
