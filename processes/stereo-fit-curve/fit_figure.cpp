#include "fit_figure.h"

#include <algorithm>

#include "models/distortion_function.h"
#include "models/monotone_cubic.h"

namespace ws {
namespace {

const char* const kModelColors[] = {"#0072b2", "#d55e00", "#009e73", "#cc79a7"};
constexpr int kCurveSamples = 600;

std::vector<double> DenseHeights(const LensTable& table) {
  std::vector<double> heights(kCurveSamples + 1);
  const double first = table.ideal.front(), last = table.ideal.back();
  for (int i = 0; i <= kCurveSamples; ++i) heights[i] = first + (last - first) * i / kCurveSamples;
  return heights;
}

// One fitted model sampled for drawing.
struct FitCurves {
  std::string name, color;
  std::vector<double> distortion_percent;  // D(r) at the dense heights
  std::vector<double> dense_error;         // r'(r) - monotone cubic of the table
  std::vector<double> row_error;           // r'(r_i) - r'_i
};

FitCurves SampleFit(const ModelFit& fit, const std::string& color, const LensTable& table,
                    const std::vector<double>& heights, double error_scale) {
  const DistortionFunction curve(fit.distortion);
  const MonotoneCubic reference(table.ideal, table.real);
  FitCurves sampled{DisplayName(fit.distortion), color, {}, {}, {}};
  for (double r : heights) {
    sampled.distortion_percent.push_back(100 * curve(r));
    sampled.dense_error.push_back(error_scale * (curve.DistortedRadius(r) - reference(r)));
  }
  for (size_t i = 0; i < table.ideal.size(); ++i)
    sampled.row_error.push_back(error_scale *
                                (curve.DistortedRadius(table.ideal[i]) - table.real[i]));
  return sampled;
}

plot::Series DesignData(const LensTable& table) {
  std::vector<double> percent = TableDistortion(table);
  for (double& value : percent) value *= 100;
  plot::Series data("design data", table.ideal, percent, plot::Style::kPoints, "black");
  data.point_type = 6;  // open circles, as in the paper
  data.point_size = 1.2;
  return data;
}

}  // namespace

std::string DisplayName(const Distortion& distortion) {
  const ModelTraits& traits = Traits(distortion.kind);
  if (distortion.kind == ModelKind::kBspline)
    return distortion.degree == 3 ? "cubic B-spline"
                                  : "degree-" + std::to_string(distortion.degree) + " B-spline";
  if (!traits.spline && !traits.angle) return std::to_string(2 * traits.terms) + "th-degree polynomial";
  return traits.name;
}

plot::Figure FitFigure(const std::string& title, const LensTable& table,
                       const std::vector<ModelFit>& fits, const std::string& unit) {
  const bool in_um = unit == "mm";
  const std::string height_label = "ideal image height [" + unit + "]";
  const std::string error_label = "fitted r′ − design r′ [" + (in_um ? std::string("µm") : unit) + "]";
  const std::string distortion_label = "distortion r'/r − 1 [%]";
  const std::vector<double> heights = DenseHeights(table);

  std::vector<FitCurves> curves;
  for (size_t m = 0; m < fits.size(); ++m)
    curves.push_back(SampleFit(fits[m], kModelColors[m % std::size(kModelColors)], table, heights,
                               in_um ? 1000.0 : 1.0));
  auto fit_line = [&](const FitCurves& c) {
    return plot::Series(c.name, heights, c.distortion_percent, plot::Style::kLines, c.color);
  };
  auto distortion_panel = [&](const std::string& panel_title) {
    plot::Panel panel(panel_title, height_label, distortion_label);
    panel.series.push_back(DesignData(table));
    panel.legend = "below";
    panel.zero_line = true;
    return panel;
  };
  auto error_panel = [&](const std::string& panel_title, const std::vector<const FitCurves*>& shown) {
    plot::Panel panel(panel_title, height_label, error_label);
    panel.legend = "below";
    panel.zero_line = true;
    for (const FitCurves* c : shown) {
      plot::Series& between =
          panel.series.emplace_back(c->name, heights, c->dense_error, plot::Style::kLines, c->color);
      between.line_width = 1.5;
      plot::Series& rows =
          panel.series.emplace_back("", table.ideal, c->row_error, plot::Style::kPoints, c->color);
      rows.point_size = 0.7;
    }
    return panel;
  };

  plot::Figure figure(title, 3, 2100, 1200);
  plot::Panel overlay = distortion_panel("All models over the design data");
  for (const FitCurves& c : curves) {
    figure.panels.push_back(distortion_panel("Fitting of the " + c.name + " model"));
    figure.panels.back().series.push_back(fit_line(c));
    overlay.series.push_back(fit_line(c));
  }
  std::vector<const FitCurves*> all;
  for (const FitCurves& c : curves) all.push_back(&c);
  figure.panels.push_back(error_panel("Fitting error (dots: at the table rows)", all));
  if (curves.size() > 1) {  // again without the worst model, to see the others
    const size_t worst = std::max_element(fits.begin(), fits.end(),
                                          [](const ModelFit& a, const ModelFit& b) {
                                            return a.errors.max_abs < b.errors.max_abs;
                                          }) -
                         fits.begin();
    std::vector<const FitCurves*> others = all;
    others.erase(others.begin() + worst);
    figure.panels.push_back(
        error_panel("Fitting error without the " + curves[worst].name, others));
  }
  figure.panels.push_back(overlay);
  return figure;
}

}  // namespace ws
