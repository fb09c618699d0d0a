// stereo-export: a calibration file (stereo-calibrate --out) in the format
// of another tool, into a folder (interop/export.h, docs/export.md). Exact
// where the tool has the camera's model; otherwise it says so and prints
// the error of what it wrote instead.
//
//   stereo-export calib.yaml --to mrcal mrcal/

#include <array>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "interop/export.h"
#include "rig/rig_file.h"

int main(int argc, char** argv) {
  CLI::App app{
      "Writes a calibration file (stereo-calibrate --out) in another tool's format into the folder "
      "OUT: opencv-stereo (stereo.yaml: K D R T R1 R2 P1 P2 Q, and maps.yml.gz: the pinhole "
      "rectification's cv::remap tables), ros (left.yaml, right.yaml: camera_info), kalibr "
      "(camchain.yaml), mrcal (camera-0.cameramodel, camera-1.cameramodel). A camera whose model "
      "the format has is written exactly; otherwise the export says so, in the files and here, "
      "and prints the error of what it wrote instead (the maps; Kalibr's closest model and mrcal's "
      "LENSMODEL_SPLINED_STEREOGRAPHIC, both fitted within the lens circle, docs/export.md)."};
  std::string in, format, out;
  app.add_option("calibration", in, "the calibration file")->required()->check(CLI::ExistingFile);
  app.add_option("--to", format, "opencv-stereo, ros, kalibr or mrcal")
      ->required()
      ->check(CLI::IsMember({"opencv-stereo", "ros", "kalibr", "mrcal"}));
  app.add_option("out", out, "the folder to write into (created when missing)")->required();
  std::string calibration_report;
  app.add_option("--report", calibration_report,
                 "the calibration's report (stereo-calibrate --report, or NAME.report.json beside its --out): "
                 "mrcal's spline and Kalibr's closest model are then fitted only out to each camera's "
                 "outermost calibrated corner "
                 "(max_observed_radius), within the model's lens circle, and is not promised beyond it "
                 "(default: over the whole observed field within the lens circle)")
      ->check(CLI::ExistingFile);
  int mrcal_nx = 0;
  app.add_option("--mrcal-nx", mrcal_nx,
                 "mrcal's spline with this many knots across, whatever its error (default: Nx 16, 20, 24 or 30, "
                 "mrcal's users' grids, the first within 0.01 px; else finer, up to 160)")
      ->check(CLI::Range(4, 1000));
  CLI11_PARSE(app, argc, argv);

  try {
    const ws::Rig file = ws::ReadCalibrationFile(in);
    std::array<double, 2> observed{INFINITY, INFINITY};
    if (!calibration_report.empty() && format == "mrcal") {
      observed = ws::CalibrationReportRadii(calibration_report, file);
      std::printf("the calibrated field, from %s: out to ideal radius %.4g (left)", calibration_report.c_str(),
                  observed[0]);
      if (!file.mono) std::printf(", %.4g (right)", observed[1]);
      std::printf("\n");
    }
    const ws::ExportReport report = ws::ExportCalibration(file, ws::ParseExportFormat(format), out, observed, mrcal_nx);
    for (const std::string& line : report.lines) std::printf("%s\n", line.c_str());
    std::printf("%s: %s into %s:", report.exact ? "exact" : "NOT EXACT", format.c_str(), out.c_str());
    for (const std::string& name : report.files) std::printf(" %s", name.c_str());
    if (!report.exact) std::printf(" (error up to %.4g px)", report.max_error_px);
    std::printf("\n");
  } catch (const std::exception& error) {
    std::cerr << "stereo-export: " << error.what() << "\n";
    return 1;
  }
  return 0;
}
