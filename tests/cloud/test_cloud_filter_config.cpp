// Loading and checking CloudFilterConfig.
#include <gtest/gtest.h>

#include <fstream>
#include <ostream>
#include <string>

#include "cloud/cloud_filter.h"
#include "cloud_test_support.h"

namespace {

using ws::testing::ScratchFile;

// Every field, none at its default.
const std::string kFullConfig = R"(%YAML:1.0
z_min: 0.5
z_max: 8
voxel_enabled: false
voxel_leaf: 0.02
outliers_enabled: false
outliers_mean_k: 30
outliers_stddev_mul: 1.5
plane_enabled: false
plane_distance: 0.01
plane_max_iterations: 500
plane_min_inliers: 50
)";

// kFullConfig with the line starting with `field:` replaced by `line`
// (removed when `line` is empty).
std::string WithLine(const std::string& field, const std::string& line) {
  std::string text = kFullConfig;
  const size_t begin = text.find("\n" + field + ":") + 1;
  const size_t end = text.find('\n', begin) + 1;
  return text.replace(begin, end - begin, line.empty() ? "" : line + "\n");
}

void ExpectSameConfig(const ws::CloudFilterConfig& actual, const ws::CloudFilterConfig& expected) {
  EXPECT_EQ(actual.z_min, expected.z_min);
  EXPECT_EQ(actual.z_max, expected.z_max);
  EXPECT_EQ(actual.voxel_enabled, expected.voxel_enabled);
  EXPECT_EQ(actual.voxel_leaf, expected.voxel_leaf);
  EXPECT_EQ(actual.outliers_enabled, expected.outliers_enabled);
  EXPECT_EQ(actual.outliers_mean_k, expected.outliers_mean_k);
  EXPECT_EQ(actual.outliers_stddev_mul, expected.outliers_stddev_mul);
  EXPECT_EQ(actual.plane_enabled, expected.plane_enabled);
  EXPECT_EQ(actual.plane_distance, expected.plane_distance);
  EXPECT_EQ(actual.plane_max_iterations, expected.plane_max_iterations);
  EXPECT_EQ(actual.plane_min_inliers, expected.plane_min_inliers);
}

TEST(CloudFilterConfig, LoadsEveryField) {
  ws::CloudFilterConfig expected;
  expected.z_min = 0.5;
  expected.z_max = 8;
  expected.voxel_enabled = false;
  expected.voxel_leaf = 0.02;
  expected.outliers_enabled = false;
  expected.outliers_mean_k = 30;
  expected.outliers_stddev_mul = 1.5;
  expected.plane_enabled = false;
  expected.plane_distance = 0.01;
  expected.plane_max_iterations = 500;
  expected.plane_min_inliers = 50;
  const ScratchFile file("config.yaml", kFullConfig);
  ExpectSameConfig(ws::LoadCloudFilterConfig(file.path()), expected);
}

// The YAML example in cloud_filter_config.h, without its comment markers.
std::string DocumentedExample() {
  std::ifstream header(WS_SOURCE_DIR "/common/cloud/cloud_filter_config.h");
  std::string line, yaml;
  while (std::getline(header, line) && line != "//   %YAML:1.0") continue;
  for (yaml = "%YAML:1.0\n"; std::getline(header, line) && line.rfind("//   ", 0) == 0;)
    yaml += line.substr(5) + "\n";
  return yaml;
}

TEST(CloudFilterConfig, DocumentedExampleLoadsAsTheDefaults) {
  const ScratchFile file("config.yaml", DocumentedExample());
  ExpectSameConfig(ws::LoadCloudFilterConfig(file.path()), ws::CloudFilterConfig{});
}

// The ConfigError message loading `path` gives; "loaded" when there is none.
std::string LoadError(const std::string& path) {
  try {
    ws::LoadCloudFilterConfig(path);
  } catch (const ws::ConfigError& e) {
    return e.what();
  }
  return "loaded";
}

struct BadConfig {
  std::string name;  // of the test case
  std::string text;
  std::string message;  // what the error must say after "PATH: "
};

void PrintTo(const BadConfig& bad, std::ostream* out) { *out << bad.name; }

class CloudFilterConfigErrors : public ::testing::TestWithParam<BadConfig> {};

TEST_P(CloudFilterConfigErrors, NameFileFieldAndReason) {
  const ScratchFile file("config.yaml", GetParam().text);
  EXPECT_EQ(LoadError(file.path()), file.path() + ": " + GetParam().message);
}

INSTANTIATE_TEST_SUITE_P(
    CloudFilterConfig, CloudFilterConfigErrors,
    ::testing::Values(
        BadConfig{"Missing", WithLine("voxel_leaf", ""), "field 'voxel_leaf': missing"},
        BadConfig{"NotANumber", WithLine("z_max", "z_max: far"), "field 'z_max': must be a number"},
        BadConfig{"NotAnInteger", WithLine("outliers_mean_k", "outliers_mean_k: 20.5"),
                  "field 'outliers_mean_k': must be an integer"},
        BadConfig{"NotABoolean", WithLine("plane_enabled", "plane_enabled: 1"),
                  "field 'plane_enabled': must be true or false"},
        BadConfig{"Unknown", kFullConfig + "voxel_size: 0.01\n",
                  "field 'voxel_size': unknown field"},
        BadConfig{"Repeated", kFullConfig + "z_min: 0.1\n", "field 'z_min': given more than once"},
        BadConfig{"NotPositive", WithLine("voxel_leaf", "voxel_leaf: -0.01"),
                  "field 'voxel_leaf': must be > 0, got -0.01"},
        BadConfig{"EmptyDepthRange", WithLine("z_max", "z_max: 0.4"),
                  "field 'z_max': must be greater than z_min (0.5), got 0.4"},
        BadConfig{"Infinite", WithLine("outliers_stddev_mul", "outliers_stddev_mul: .inf"),
                  "field 'outliers_stddev_mul': must be a finite number, got inf"},
        BadConfig{"TooFewForAPlane", WithLine("plane_min_inliers", "plane_min_inliers: 2"),
                  "field 'plane_min_inliers': must be >= 3, got 2"},
        BadConfig{"NotAMap", "%YAML:1.0\n- 1\n", "the file must be a YAML map of field: value"},
        // OpenCV 4.6's YAML reader would never return on this one.
        BadConfig{"LessIndentedThanTheFirstLine", "%YAML:1.0\n z_min: 0.3\nabc-\n",
                  "line 3: indented less than line 2, where the top level starts"}),
    [](const ::testing::TestParamInfo<BadConfig>& info) { return info.param.name; });

TEST(CloudFilterConfig, FileThatIsNotOpenCvYamlIsNamed) {
  const ScratchFile no_header("config.yaml", kFullConfig.substr(kFullConfig.find('\n') + 1));
  const std::string error = LoadError(no_header.path());
  EXPECT_EQ(error.rfind(no_header.path() + ": not YAML that OpenCV reads", 0), 0) << error;
  EXPECT_EQ(LoadError("/nonexistent/cloud.yaml"), "/nonexistent/cloud.yaml: cannot open the file");
}

TEST(CloudFilterConfig, FilterRejectsAnInvalidConfig) {
  ws::CloudFilterConfig config;
  config.outliers_mean_k = 0;
  EXPECT_THROW(ws::CloudFilter{config}, ws::ConfigError);
  EXPECT_NO_THROW(ws::CloudFilter{ws::CloudFilterConfig{}});
}

}  // namespace
