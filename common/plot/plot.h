// PNG plots through gnuplot: a Figure is one or more Panels (laid out in a
// grid by gnuplot's multiplot), each with axes, labels, a legend and any
// number of Series drawn as lines and/or points.
//
//   plot::Figure figure("Lens fit");
//   plot::Panel& panel = figure.panels.emplace_back("Distortion", "r [mm]", "D [%]");
//   panel.series.emplace_back("data", r, d, plot::Style::kPoints);
//   panel.series.emplace_back("B-spline", dense_r, dense_d);
//   plot::WritePng(figure, "fit.png");
//
// Needs the `gnuplot` executable on PATH (Debian: gnuplot-nox); uses its
// pngcairo terminal, or png where cairo is missing.
#pragma once

#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace ws::plot {

enum class Style { kLines, kPoints, kLinesPoints };

struct Series {
  Series(std::string title, std::vector<double> x, std::vector<double> y,
         Style style = Style::kLines, std::string color = "")
      : title(std::move(title)), x(std::move(x)), y(std::move(y)), style(style),
        color(std::move(color)) {}

  std::string title;  // legend entry; empty: not in the legend
  std::vector<double> x, y;
  Style style;
  std::string color;  // gnuplot colour ("#0072b2", "dark-red"); empty: by position in the panel
  double line_width = 2.0;
  int point_type = 7;  // gnuplot point type: 7 filled circle, 6 open circle, 5 filled square, ...
  double point_size = 0.8;
};

// Values on a regular grid drawn as colours under a panel's series, with a
// colour bar: cell (i, j) centred at (x0 + i dx, y0 + j dy), row-major
// (values[j * cols + i]); NaN cells are grey, and the colour bar's label
// says what they are (`missing`), so that none reads as the scale's 0.
struct Heatmap {
  int cols = 0, rows = 0;
  double x0 = 0, y0 = 0, dx = 1, dy = 1;
  std::vector<double> values;
  std::string label;        // the colour bar's: what and which unit
  std::string missing = "no value";  // what a NaN cell means
  double max = NAN;         // top of the colour scale; NaN: the largest value
};

struct Panel {
  Panel(std::string title, std::string x_label, std::string y_label)
      : title(std::move(title)), x_label(std::move(x_label)), y_label(std::move(y_label)) {}

  std::string title;
  std::string x_label, y_label;
  std::vector<Series> series;
  // gnuplot key position inside the plot ("top right", "bottom left", ...);
  // "below": under the x label, where it never covers a curve; "off" hides it.
  std::string legend = "top right";
  bool zero_line = false;            // draw the line y = 0
  // Image coordinates: y grows downward (the axis reversed; labels stay
  // positive) and x, y are drawn to the same scale.
  bool image_axes = false;
  std::optional<Heatmap> heatmap;
};

struct Figure {
  explicit Figure(std::string title, int columns = 1, int width = 1200, int height = 800)
      : title(std::move(title)), columns(columns), width(width), height(height) {}

  std::string title;
  int columns;  // panels per row
  int width, height;  // pixels
  std::vector<Panel> panels;
};

struct PlotError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Renders the figure into a PNG file. Throws PlotError if the figure is
// empty, a series' x and y differ in length, gnuplot is missing or fails
// (with gnuplot's own message).
void WritePng(const Figure& figure, const std::string& png_path);

}  // namespace ws::plot
