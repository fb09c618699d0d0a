// stereo-compare: how much two calibrations of one rig differ, in pixels
// across each camera's image, after the small rotation between their camera
// frames that fits best (calib/evaluate/projection_diff.h; mrcal's
// show-projection-diff). Two models, two days, two rigs: whether a
// recalibration changed anything real. Either calibration may be another
// tool's: mrcal's .cameramodel (or its output folder), Kalibr's camchain,
// OpenCV's calibration YAML (interop/any_rig.h).
//
//   stereo-compare old.yaml new.yaml --plot diff.png --report diff.json
//   stereo-compare calib.yaml mrcal-left/camera-0.cameramodel

#include <cstdio>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "calib/evaluate/projection_diff.h"
#include "calib/node/calib_plots.h"
#include "calib/node/report.h"
#include "interop/any_rig.h"
#include "runtime/atomic_file.h"

namespace {

using namespace ws;
using namespace ws::calib;

struct Options {
  std::string a, b;
  double fit_radius = -1;  // negative: DefaultFitRadius
  bool no_rotation = false;
  int cols = 64, rows = 48;
  std::string report, plot;
};

Json DiffJson(const std::string& name, const ProjectionDiff& d) {
  Json out{{"camera", name},
           {"rms_px", d.rms_px},
           {"median_px", d.median_px},
           {"max_px", d.max_px},
           {"points", d.points},
           {"rotation_deg", d.rotation_deg},
           {"fit_points", d.fit_points}};
  out.update(ImageGridJson(d.grid, "diff_px", d.diff_px));
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Compares two calibrations of one rig (stereo-calibrate --out, or another tool's: an mrcal "
      ".cameramodel or mrcal-calibrate-cameras' output folder, a Kalibr camchain YAML, an OpenCV "
      "calibration YAML): for each camera, the pixel difference of projecting each pixel's ray of the first through the second, over a "
      "grid of the image, after the small rotation between the two camera frames that fits best "
      "near the image centre (mrcal-show-projection-diff's definition). Prints RMS, median and "
      "maximum per camera; writes a heat map and a JSON report."};
  Options o;
  app.add_option("a", o.a, "the first calibration (its image is the grid's)")
      ->required()
      ->check(CLI::ExistingPath);
  app.add_option("b", o.b, "the second calibration")->required()->check(CLI::ExistingPath);
  app.add_option("--fit-radius", o.fit_radius,
                 "fit the rotation to the grid points within this many pixels of the image "
                 "centre (default: a sixth of the smaller image side)")
      ->check(CLI::PositiveNumber);
  app.add_flag("--no-rotation", o.no_rotation,
               "compare in the files' own camera frames (no rotation fitted)");
  app.add_option("--cols", o.cols, "grid points across")->capture_default_str()->check(CLI::Range(2, 1000));
  app.add_option("--rows", o.rows, "grid points down")->capture_default_str()->check(CLI::Range(2, 1000));
  app.add_option("--report", o.report, "write the differences (JSON) here");
  app.add_option("--plot", o.plot, "draw the difference maps into this PNG (needs gnuplot)");
  CLI11_PARSE(app, argc, argv);

  try {
    const AnyRig a = LoadAnyRig(o.a), b = LoadAnyRig(o.b);
    std::vector<std::pair<std::string, ProjectionDiff>> diffs;
    for (int side = 0; side < ((a.mono || b.mono) ? 1 : 2); ++side) {
      const CameraProjection& ca = side == 0 ? *a.left : *a.right;
      const CameraProjection& cb = side == 0 ? *b.left : *b.right;
      const double radius = o.no_rotation ? 0 : o.fit_radius > 0 ? o.fit_radius : DefaultFitRadius(ca);
      diffs.emplace_back(side == 0 ? "left" : "right",
                         CompareProjection(ca, cb, radius, o.cols, o.rows));
    }
    const std::string title = "difference of " + o.b + " (" + b.format + " " + b.left->Name() +
                              ") from " + o.a + " (" + a.format + " " + a.left->Name() + ")";
    std::printf("%s: %s's pixel rays projected through %s\n", title.c_str(), o.a.c_str(), o.b.c_str());
    for (const auto& [name, d] : diffs)
      std::printf("%-5s: rms %.4f px, median %.4f px, max %.4f px over %d grid points; rotation "
                  "%.4f deg fitted to %d points\n",
                  name.c_str(), d.rms_px, d.median_px, d.max_px, d.points, d.rotation_deg,
                  d.fit_points);
    if (!a.mono && !b.mono)
      std::printf("stereo: baseline %.6f m against %.6f m\n", b.T.norm(), a.T.norm());
    if (!o.report.empty()) {
      Json cameras = Json::array();
      for (const auto& [name, d] : diffs) cameras.push_back(DiffJson(name, d));
      const Json report{{"a", o.a}, {"b", o.b}, {"cameras", cameras}};
      WriteFileAtomically(o.report, report.dump(2) + "\n");
    }
    if (!o.plot.empty())
      WriteProjectionDiffPng(diffs, title, o.plot);
  } catch (const std::exception& error) {
    std::cerr << "stereo-compare: " << error.what() << "\n";
    return 1;
  }
  return 0;
}
