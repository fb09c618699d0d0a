// The filter chain's settings: as stereo-cloud's options and config keys,
// and their checks.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cloud/cloud_filter.h"
#include "cloud/cloud_filter_options.h"
#include "runtime/process_cli.h"

namespace {

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

// Parses `args` as stereo-cloud's command line would (ProcessCli: --config
// and the flags); the exit code when parsing stops the process.
std::optional<int> Parse(std::vector<std::string> args, ws::CloudFilterConfig* config) {
  ws::ProcessCli cli("stereo-cloud", "test");
  ws::AddCloudFilterOptions(cli.app(), config);
  args.insert(args.begin(), "stereo-cloud");
  std::vector<char*> argv;
  for (std::string& arg : args) argv.push_back(arg.data());
  return cli.Parse(int(argv.size()), argv.data());
}

TEST(CloudFilterOptions, EveryOptionSetsItsField) {
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
  ws::CloudFilterConfig config;
  ASSERT_EQ(Parse({"--z-min", "0.5", "--z-max", "8", "--voxel", "false", "--voxel-leaf", "0.02",
                   "--outliers", "false", "--outliers-mean-k", "30", "--outliers-stddev-mul",
                   "1.5", "--plane", "false", "--plane-distance", "0.01",
                   "--plane-max-iterations", "500", "--plane-min-inliers", "50"},
                  &config),
            std::nullopt);
  ExpectSameConfig(config, expected);
}

TEST(CloudFilterOptions, ShippedConfigHoldsTheDefaults) {
  ws::CloudFilterConfig config;
  config.z_max = 99;  // the file must set it back
  config.voxel_enabled = false;
  ASSERT_EQ(Parse({"--config", "config/stereo-cloud.yaml"}, &config), std::nullopt);
  ExpectSameConfig(config, ws::CloudFilterConfig{});
}

TEST(CloudFilterOptions, NotANumberOrSwitchStopsParsing) {
  ws::CloudFilterConfig config;
  EXPECT_NE(Parse({"--z-max", "far"}, &config), std::nullopt);
  EXPECT_NE(Parse({"--voxel", "maybe"}, &config), std::nullopt);
  EXPECT_NE(Parse({"--outliers-mean-k", "20.5"}, &config), std::nullopt);
}

// The ConfigError message of ValidateCloudFilterConfig; "valid" when there is none.
std::string ValidationError(const ws::CloudFilterConfig& config) {
  try {
    ws::ValidateCloudFilterConfig(config);
  } catch (const ws::ConfigError& e) {
    return e.what();
  }
  return "valid";
}

TEST(CloudFilterOptions, ValuesOutOfRangeNameTheOptionAndReason) {
  const ws::CloudFilterConfig good;
  EXPECT_EQ(ValidationError(good), "valid");
  auto with = [&](auto change) {
    ws::CloudFilterConfig config = good;
    change(config);
    return ValidationError(config);
  };
  EXPECT_EQ(with([](auto& c) { c.voxel_leaf = -0.01; }), "--voxel-leaf: must be > 0, got -0.01");
  EXPECT_EQ(with([](auto& c) { c.z_min = 0.5, c.z_max = 0.4; }),
            "--z-max: must be greater than --z-min (0.5), got 0.4");
  EXPECT_EQ(with([](auto& c) { c.z_min = -1; }), "valid") << "a lat-lon cloud reaches behind the image plane";
  EXPECT_EQ(with([](auto& c) { c.z_min = -INFINITY; }), "--z-min: must be a finite number, got -inf");
  EXPECT_EQ(with([](auto& c) { c.outliers_stddev_mul = INFINITY; }),
            "--outliers-stddev-mul: must be a finite number, got inf");
  EXPECT_EQ(with([](auto& c) { c.outliers_mean_k = 0; }), "--outliers-mean-k: must be >= 1, got 0");
  EXPECT_EQ(with([](auto& c) { c.plane_min_inliers = 2; }),
            "--plane-min-inliers: must be >= 3, got 2");
  EXPECT_EQ(with([](auto& c) { c.plane_max_iterations = 0; }),
            "--plane-max-iterations: must be >= 1, got 0");
  EXPECT_EQ(with([](auto& c) { c.plane_distance = 0; }), "--plane-distance: must be > 0, got 0");
}

TEST(CloudFilterOptions, FilterRejectsAnInvalidConfig) {
  ws::CloudFilterConfig config;
  config.outliers_mean_k = 0;
  EXPECT_THROW(ws::CloudFilter{config}, ws::ConfigError);
  EXPECT_NO_THROW(ws::CloudFilter{ws::CloudFilterConfig{}});
}

}  // namespace
