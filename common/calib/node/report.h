// The calibration report (--report FILE.json), the contract tools and tests
// read:
//
//   {"model": "bspline",
//    "cameras": [{"name": "left", "rms_px": 0.11, "views": 30, "points": 1620, "outliers": 0,
//                 and the camera's fields as models/camera_field_table.h names them:
//                 "image_width": 1280, "image_height": 960, "fx": ..., "fy": ..., "cx": ...,
//                 "cy": ..., "model": "bspline", "degree": 3, "knots": [...] (the splines),
//                 "alpha": [...] (or "k": [...]), "p1": ..., "p2": ..., "nonradial": {...}
//                 (with a field or a tilt),
//                 "stddev": {"fx": ..., ...}, ...}, {"name": "right", ...}],
//    "stereo": {"rms_px": ..., "R": [9, row-major], "T": [3], "baseline_m": ..., ...},
//    "solve_seconds": ...}
//
// Besides those keys each camera has "view_rms" (per input view,
// null where the view was not used), "invalid_points", "skipped",
// "init_method", "max_observed_radius" and "residual_grid" (rows, cols,
// count, mean_x, mean_y, rms per cell, row-major); "stereo" has "views",
// "view_rms" and "stddev" (rx ry rz angle-axis radians, tx ty tz metres),
// and the top level "flow" ("joint" or "paper").
// Each camera also has "heldout_rms_px" (the K-fold cross-validated RMS,
// heldout.h; null when not computed) beside "rms_px",
// "heldout_fold_rms_px" (per fold), "heldout_extrapolated_corners" (held-out
// corners farther out than every training corner, left out) and "knot_curve" (--knots auto: per
// count tried {"knots", "rms_px", "heldout_rms_px", "fold_rms_px"}; empty
// otherwise). With the board's bow estimated, "board_warp" {"x2_mm",
// "y2_mm", "centre_mm", "stddev_x2_mm", "stddev_y2_mm"}; with --board-warp
// auto, "board_warp_choice" {"kept", "flat_heldout_rms_px",
// "warped_heldout_rms_px", "x2_mm", "y2_mm", "stddev_x2_mm", "stddev_y2_mm"}
// (the bow this camera's views estimated, kept or not). "field_curve"
// (--nonradial auto: none, the tilt, then
// every field tried, {"tilt", "cols", "rows", "smoothness", "rms_px",
// "heldout_rms_px", "fold_rms_px"};
// empty otherwise) and "field_chosen" (its index).
// Each camera has "choices": every choice made for it by the rule of
// selection.h (docs/calibration.md), in order, as SelectionReport.
// With several models: {"models": [one object as above per model],
// "table_ii": [{"model", "left_rms_px", "right_rms_px", "stereo_rms_px",
// "left_heldout_rms_px", "right_heldout_rms_px", "coeffs", "chosen"}],
// "chosen": the model published, "model_choice": how (SelectionReport),
// "solve_seconds": the wall clock of the whole}.
// Every number is written so that it reads back bit-identical; only
// "solve_seconds" differs between runs on the same input.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "calib/calibrate.h"
#include "calib/evaluate/image_grid.h"

namespace ws::calib {

// Keys in the order above.
using Json = nlohmann::ordered_json;

Json CameraReport(const CameraCalibration& camera);
// Values on an image grid: {"cols", "rows", "step_px": [x, y], KEY: [row-major,
// null where not finite]}.
Json ImageGridJson(const ImageGrid& grid, const std::string& key,
                   const std::vector<double>& values);
Json StereoReport(const StereoCalibration& calibration);
// One choice: {"choice", "camera" (null for the rig), "candidates": [{"name",
// "parameters", "heldout_rms_px" (null: not scored), "fold_rms_px",
// "corners", "excess_px", "spread_px", "failed" (null: scored)}], "best",
// "chosen" (indices, null: none scored), "why"}.
Json SelectionReport(const Selection& selection);
// Every model under "models": a solved one as StereoReport, a failed one as
// {"model": NAME, "error": "..."}; Table II of the solved ones.
Json ModelsReport(const ModelCalibrations& calibrations);

}  // namespace ws::calib
