// stereo-fit-curve, run as a user would.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "models/lens_table.h"
#include "models/theia_lens.h"

namespace ws {
namespace {

namespace fs = std::filesystem;

const std::string kTool = WS_BINARY_DIR "/bin/stereo-fit-curve";
const std::string kTable = WS_SOURCE_DIR "/config/lenses/theia-my125m-like.csv";

struct ToolRun {
  int exit_code;
  std::string output;  // stdout and stderr
};

ToolRun RunTool(const std::string& arguments) {
  ToolRun run{-1, ""};
  FILE* pipe = popen(("'" + kTool + "' " + arguments + " 2>&1").c_str(), "r");
  if (!pipe) return run;
  char buffer[4096];
  while (size_t n = fread(buffer, 1, sizeof buffer, pipe)) run.output.append(buffer, n);
  const int status = pclose(pipe);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

fs::path OutputDir() {
  const fs::path dir = fs::path(WS_BINARY_DIR) / "test-output" / "fit-curve";
  fs::create_directories(dir);
  return dir;
}

nlohmann::json ReadJson(const fs::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

const nlohmann::json& ModelNamed(const nlohmann::json& report, const std::string& name) {
  for (const auto& model : report.at("models"))
    if (model.at("name") == name) return model;
  throw std::runtime_error("no model " + name + " in the report");
}

TEST(StereoFitCurve, FitsTheShippedTableAsThePaperDid) {
  const fs::path report_path = OutputDir() / "fit.json", plot_path = OutputDir() / "fit.png";
  fs::remove(plot_path);
  const ToolRun run = RunTool("'" + kTable + "' --report '" + report_path.string() + "' --plot '" +
                          plot_path.string() + "'");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  std::printf("%s", run.output.c_str());
  const nlohmann::json report = ReadJson(report_path);
  ASSERT_EQ(report.at("models").size(), 3u);
  EXPECT_EQ(report["models"][0]["name"], "bspline");
  EXPECT_EQ(report["models"][1]["name"], "poly6");
  EXPECT_EQ(report["models"][2]["name"], "poly12");
  for (const auto& model : report["models"])
    for (const char* key : {"rms_error", "max_abs_error", "max_abs_error_between"})
      EXPECT_TRUE(model.at(key).is_number()) << model["name"] << " " << key;

  const LensTable table = TheiaLikeLensTable();
  const double height_range = table.ideal.back() - table.ideal.front();
  const auto& bspline = ModelNamed(report, "bspline");
  const auto& poly6 = ModelNamed(report, "poly6");
  const auto& poly12 = ModelNamed(report, "poly12");
  EXPECT_LT(bspline["max_abs_error"].get<double>(), 1e-6 * height_range);
  EXPECT_LE(bspline["rms_error"].get<double>(), bspline["max_abs_error"].get<double>());
  EXPECT_LE(poly12["max_abs_error"].get<double>(), poly6["max_abs_error"].get<double>() / 5);
  EXPECT_LE(poly12["max_abs_error_between"].get<double>(),
            poly6["max_abs_error_between"].get<double>() / 5);
  // The polynomials' errors are real (micrometres), not numerical noise.
  EXPECT_GT(poly12["max_abs_error"].get<double>(), 1e-4);
  EXPECT_GT(poly6["max_abs_error"].get<double>(), 5e-3);

  std::ifstream png(plot_path, std::ios::binary);
  char signature[8] = {};
  png.read(signature, 8);
  EXPECT_EQ(std::string(signature, 8), "\x89PNG\r\n\x1a\n");
  EXPECT_GT(fs::file_size(plot_path), 20000u);  // a drawn figure, not an empty canvas
}

TEST(StereoFitCurve, TakesTheTableAsOptionAndAsPercent) {
  const fs::path positional = OutputDir() / "positional.json", option = OutputDir() / "option.json",
                 percent = OutputDir() / "percent.json", percent_table = OutputDir() / "percent.csv";
  ASSERT_EQ(RunTool("'" + kTable + "' --report '" + positional.string() + "'").exit_code, 0);
  ASSERT_EQ(RunTool("--table '" + kTable + "' --report '" + option.string() + "'").exit_code, 0);
  EXPECT_EQ(ReadJson(positional)["models"], ReadJson(option)["models"]);

  const LensTable table = TheiaLikeLensTable();
  {
    std::ofstream out(percent_table);
    out.precision(17);
    out << "ideal_height_mm,distortion_percent\n";
    for (size_t i = 0; i < table.ideal.size(); ++i)
      out << table.ideal[i] << ","
          << (table.ideal[i] > 0 ? 100 * (table.real[i] / table.ideal[i] - 1) : 0.0) << "\n";
  }
  const ToolRun run = RunTool("'" + percent_table.string() + "' --percent --report '" +
                          percent.string() + "'");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  for (const char* name : {"bspline", "poly6", "poly12"}) {
    const double heights = ModelNamed(ReadJson(option), name)["max_abs_error_between"];
    const double percents = ModelNamed(ReadJson(percent), name)["max_abs_error_between"];
    EXPECT_NEAR(percents, heights, 1e-9) << name;
  }
}

TEST(StereoFitCurve, ExplainsBadInput) {
  const ToolRun help = RunTool("--help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.output.find("--percent"), std::string::npos) << help.output;

  EXPECT_NE(RunTool("").exit_code, 0);
  const ToolRun missing = RunTool("/nonexistent/lens.csv");
  EXPECT_NE(missing.exit_code, 0);
  EXPECT_NE(missing.output.find("/nonexistent/lens.csv"), std::string::npos) << missing.output;

  const fs::path bad = OutputDir() / "bad.csv";
  std::ofstream(bad) << "ideal,real\n0,0\n1,1.01\n2,1.0\n3,3\n";
  const ToolRun decreasing = RunTool("'" + bad.string() + "'");
  EXPECT_EQ(decreasing.exit_code, 1);
  EXPECT_NE(decreasing.output.find(bad.string() + ":4: real height 1 is not greater than 1.01"),
            std::string::npos)
      << decreasing.output;
}

}  // namespace
}  // namespace ws
