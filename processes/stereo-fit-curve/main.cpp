// stereo-fit-curve: fits the B-spline, 6th- and 12th-degree polynomial radial
// distortion models to a lens design table (paper Sec. VII-A), prints their
// errors, and writes a JSON report and a figure.
//
//   stereo-fit-curve config/lenses/theia-my125m-like.csv --report fit.json --plot fit.png

#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "fit_figure.h"
#include "models/curve_fit.h"
#include "models/lens_table.h"
#include "models/model_registry.h"
#include "runtime/atomic_file.h"

namespace {

using namespace ws;

struct Options {
  std::string table;
  bool percent = false;
  int degree = 3;
  std::string unit = "mm";
  std::string report;
  std::string plot;
};

// The B-spline by collocation, the polynomials by least squares.
std::vector<ModelFit> FitModels(const LensTable& table, int degree) {
  std::vector<Distortion> fits{FitBsplineByCollocation(table, degree)};
  for (const ModelKind kind : {ModelKind::kPoly6, ModelKind::kPoly12})
    fits.push_back(FitByLeastSquares(MakeModel(Distortion{kind, 0, {}, {}}, Coefficients::kAll), table));
  std::vector<ModelFit> results;
  for (const Distortion& fit : fits) results.push_back({fit, MeasureFitErrors(fit, table)});
  return results;
}

void PrintTable(const Options& options, const LensTable& table, const std::vector<ModelFit>& fits) {
  std::printf("%s: %zu rows, ideal height %g to %g %s\n", options.table.c_str(), table.ideal.size(),
              table.ideal.front(), table.ideal.back(), options.unit.c_str());
  std::printf("%-8s %7s %15s %15s %23s\n", "model", "coeffs", "rms error", "max error",
              "max error between rows");
  for (const ModelFit& fit : fits)
    std::printf("%-8s %7zu %12.3e %-2s %12.3e %-2s %20.3e %-2s\n", ModelName(fit.distortion.kind).c_str(),
                fit.distortion.coeffs.size(), fit.errors.rms, options.unit.c_str(),
                fit.errors.max_abs, options.unit.c_str(), fit.errors.max_abs_between,
                options.unit.c_str());
}

void WriteReport(const Options& options, const LensTable& table, const std::vector<ModelFit>& fits) {
  nlohmann::ordered_json models = nlohmann::ordered_json::array();
  for (const ModelFit& fit : fits)
    models.push_back({{"name", ModelName(fit.distortion.kind)},
                      {"rms_error", fit.errors.rms},
                      {"max_abs_error", fit.errors.max_abs},
                      {"max_abs_error_between", fit.errors.max_abs_between},
                      {"degree", fit.distortion.degree},
                      {"knots", fit.distortion.knots},
                      {"coeffs", fit.distortion.coeffs}});
  const nlohmann::ordered_json report{{"table", options.table},
                              {"unit", options.unit},
                              {"rows", table.ideal.size()},
                              {"models", models}};
  WriteFileAtomically(options.report, report.dump(2) + "\n");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Fits the B-spline, 6th- and 12th-degree polynomial radial distortion models to a lens "
      "distortion table (CSV with a header: ideal image height, real image height), prints "
      "their errors and writes a JSON report and a figure."};
  Options options;
  app.add_option("table,--table", options.table,
                 "lens table CSV: ideal height, real height (same unit)")
      ->required()
      ->check(CLI::ExistingFile);
  app.add_flag("--percent", options.percent,
               "the second column is the distortion 100 (r'/r - 1) in percent");
  app.add_option("--degree", options.degree, "B-spline degree K")
      ->capture_default_str()
      ->check(CLI::Range(1, 10));
  app.add_option("--unit", options.unit, "unit of the table's heights (labels only)")
      ->capture_default_str();
  app.add_option("--report", options.report, "write the fit report (JSON) here");
  app.add_option("--plot", options.plot, "draw the fits and their errors into this PNG");
  CLI11_PARSE(app, argc, argv);

  try {
    const LensTable table = ReadLensTable(
        options.table, options.percent ? TableColumns::kPercent : TableColumns::kRealHeight);
    const std::vector<ModelFit> fits = FitModels(table, options.degree);
    PrintTable(options, table, fits);
    if (!options.report.empty()) WriteReport(options, table, fits);
    if (!options.plot.empty())
      plot::WritePng(FitFigure("Radial distortion models fitted to " + options.table, table, fits,
                               options.unit),
                     options.plot);
  } catch (const std::exception& error) {
    std::cerr << "stereo-fit-curve: " << error.what() << "\n";
    return 1;
  }
  return 0;
}
