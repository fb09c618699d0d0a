#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>

#include "plot/plot.h"

namespace ws {
namespace {

namespace fs = std::filesystem;

// Width and height from a PNG's IHDR chunk; {0, 0} if it is not a PNG.
std::pair<uint32_t, uint32_t> PngSize(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  unsigned char header[24] = {};
  in.read(reinterpret_cast<char*>(header), sizeof header);
  const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (!in || !std::equal(signature, signature + 8, header)) return {0, 0};
  auto big_endian = [&](int at) {
    return uint32_t(header[at]) << 24 | uint32_t(header[at + 1]) << 16 |
           uint32_t(header[at + 2]) << 8 | uint32_t(header[at + 3]);
  };
  return {big_endian(16), big_endian(20)};
}

fs::path OutputPath(const std::string& name) {
  const fs::path dir = fs::path(WS_BINARY_DIR) / "test-output" / "plot";
  fs::create_directories(dir);
  return dir / name;
}

TEST(Plot, DrawsPanelsWithSeriesIntoAPng) {
  plot::Figure figure("Two panels, it's quoted", 2, 900, 400);
  std::vector<double> x, y, z;
  for (int i = 0; i <= 50; ++i) {
    x.push_back(i * 0.1);
    y.push_back(std::sin(i * 0.1));
    z.push_back(0.5 * std::cos(i * 0.1));
  }
  plot::Panel& first = figure.panels.emplace_back("lines and points", "x [mm]", "y [%]");
  first.series.emplace_back("sin", x, y);
  first.series.emplace_back("cos/2", x, z, plot::Style::kPoints);
  plot::Panel& second = figure.panels.emplace_back("one series, no legend", "x", "y");
  second.series.emplace_back("", x, z, plot::Style::kLinesPoints, "dark-red");
  second.legend = "off";
  second.zero_line = true;
  const fs::path png = OutputPath("two_panels.png");
  plot::WritePng(figure, png.string());
  EXPECT_EQ(PngSize(png), (std::pair<uint32_t, uint32_t>{900, 400}));
}

TEST(Plot, DrawsAHeatMapOnImageAxesWithATwoLineTitle) {
  plot::Figure figure("heat map", 1, 500, 400);
  plot::Panel& panel = figure.panels.emplace_back("first line\nsecond \"line\"", "u [px]", "v [px]");
  panel.image_axes = true;
  plot::Heatmap map;
  map.cols = 4;
  map.rows = 3;
  map.x0 = 10;
  map.y0 = 10;
  map.dx = 20;
  map.dy = 20;
  map.values = {0, 1, 2, 3, 4, 5, NAN, 7, 8, 9, 10, 11};
  map.label = "value [px]";
  panel.heatmap = map;
  const fs::path png = OutputPath("heat_map.png");
  plot::WritePng(figure, png.string());
  EXPECT_EQ(PngSize(png), (std::pair<uint32_t, uint32_t>{500, 400}));
  map.values.pop_back();  // 11 values for 12 cells
  figure.panels.front().heatmap = map;
  EXPECT_THROW(plot::WritePng(figure, png.string()), plot::PlotError);
}

// A one-panel figure with one series.
plot::Figure OneSeries(std::vector<double> x, std::vector<double> y) {
  plot::Figure figure("one series");
  figure.panels.emplace_back("panel", "x", "y").series.emplace_back("s", x, y);
  return figure;
}

TEST(Plot, ReportsBadFigures) {
  const std::string png = OutputPath("bad.png").string();
  EXPECT_THROW(plot::WritePng(plot::Figure("empty"), png), plot::PlotError);
  EXPECT_THROW(plot::WritePng(OneSeries({1, 2, 3}, {1, 2}), png), plot::PlotError);
  EXPECT_THROW(plot::WritePng(OneSeries({}, {}), png), plot::PlotError);
  try {
    plot::WritePng(OneSeries({1, 2}, {1, 2}), "/nonexistent/dir/out.png");
    FAIL() << "no error";
  } catch (const plot::PlotError& error) {
    EXPECT_NE(std::string(error.what()).find("/nonexistent/dir/out.png"), std::string::npos)
        << error.what();
  }
  EXPECT_NO_THROW(plot::WritePng(OneSeries({1, 2}, {1, 2}), png));
}

}  // namespace
}  // namespace ws
