// OpenCV-readable YAML files: what OpenCV itself writes opens, and the
// layouts on which OpenCV 4.6's reader never returns or overflows its stack
// are refused first.
#include <gtest/gtest.h>

#include <fstream>

#include "runtime/opencv_yaml.h"
#include "test_support.h"

namespace {

TEST(OpenCvYaml, WhatOpenCvWritesOpens) {
  const std::string path = ws::test::TempDir("opencv-yaml") + "/written.yaml";
  {
    cv::FileStorage out(path, cv::FileStorage::WRITE | cv::FileStorage::FORMAT_YAML);
    out << "K" << cv::Matx33d(500, 0, 320, 0, 500, 240, 0, 0, 1);
    out << "camera" << "{" << "name" << "left" << "coeffs" << "[" << 0.1 << -0.2 << "]" << "}";
  }
  cv::FileStorage in;
  ASSERT_NO_THROW(ws::OpenOpenCvYaml(in, path));
  EXPECT_EQ(in["camera"]["name"].string(), "left");
  EXPECT_EQ(cv::Mat(in["K"].mat()).at<double>(0, 2), 320);
}

TEST(OpenCvYaml, LayoutsOpenCvWouldHangOnAreRefusedWithTheirLine) {
  auto error = [](const std::string& text) {
    try {
      ws::CheckOpenCvYamlLayout(text);
    } catch (const ws::YamlFileError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(error("%YAML:1.0\n---\n# top\na:\n  b: 1\n# back at 0\nc: 2\n"), "");
  EXPECT_EQ(error("%YAML:1.0\n  a: 1\n# comment\nxyz-\n"),
            "line 4: indented less than line 2, where the top level starts");
  EXPECT_EQ(error("%YAML:1.0\n----n\nx\n"), "line 2: nothing may follow '---' on its line");
  EXPECT_EQ(error("%YAML:1.0\n--- # start\na: 1\n"), "");
  EXPECT_EQ(error("%YAML:1.0\na: 1\n...\n-\n"),
            "line 3: '...' (the end of a YAML document) is not supported");
  // OpenCV recurses per level: some 50000 levels overflow its stack.
  EXPECT_EQ(error("%YAML:1.0\na: " + std::string(65, '[') + "\n"), "line 2: nested more than 64 deep");
  EXPECT_EQ(error("%YAML:1.0\na:\n" + std::string(40, '{') + "\n" + std::string(40, '[') + "\n"),
            "line 4: nested more than 64 deep");
  std::string dashes = "%YAML:1.0\na: ";
  for (int i = 0; i < 65; ++i) dashes += "- ";
  EXPECT_EQ(error(dashes + "x\n"), "line 2: nested more than 64 deep");
  EXPECT_EQ(error("%YAML:1.0\na: \"[[[[\" # [[[[\nb: [[[1]], {c: [2]}]\nd: - - 3\n"), "");
  EXPECT_THROW(
      {
        cv::FileStorage in;
        ws::OpenOpenCvYaml(in, "/nonexistent/x.yaml");
      },
      ws::YamlFileError);
}

}  // namespace
