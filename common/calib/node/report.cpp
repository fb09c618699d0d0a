#include "calib/node/report.h"

#include <cmath>
#include <stdexcept>
#include <type_traits>

#include "calib/node/table2.h"
#include "models/camera_field_table.h"
#include "models/model_registry.h"

namespace ws::calib {
namespace {

Json Numbers(const std::vector<double>& values) {
  Json out = Json::array();
  for (double v : values) out.push_back(v);
  return out;
}

// The fields a visit of the camera table (models/camera_field_table.h)
// gives, as a JSON object: the model by its name, the non-radial part an
// object of its own.
template <class ForEach>
Json Fields(ForEach&& for_each) {
  Json j = Json::object();
  for_each([&](const std::string& key, const auto& value) {
    using T = std::decay_t<decltype(value)>;
    if constexpr (std::is_same_v<T, NonRadial>)
      j[key] = Fields([&](auto&& visit) { ForEachNonRadialField(value, visit); });
    else if constexpr (std::is_same_v<T, ModelKind>)
      j[key] = ModelName(value);
    else if constexpr (std::is_class_v<T>)  // a vector or an array of numbers
      j[key] = Numbers(std::vector<double>(value.begin(), value.end()));
    else
      j[key] = value;
  });
  return j;
}

// Per-view RMS with null for views not used.
Json ViewRmsJson(const std::vector<double>& rms) {
  Json out = Json::array();
  for (double v : rms) out.push_back(v < 0 ? Json() : Json(v));
  return out;
}

// projection_uncertainty.h.
Json UncertaintyReport(const ProjectionUncertainty& u) {
  Json out;
  out["definition"] =
      "worst-direction 1-sigma of projecting a fixed camera-frame ray, from the solve's "
      "covariance with the board poses marginalised (docs/calibration.md: Projection uncertainty)";
  out.update(ImageGridJson(u.grid, "sigma_px", u.sigma_px));
  out["observed"] = std::vector<int>(u.observed.begin(), u.observed.end());
  out["median_px"] = u.median_px;
  out["worst_px"] = u.worst_px;
  return out;
}

const char* FlowName(StereoFlow flow) { return flow == StereoFlow::kJoint ? "joint" : "paper"; }

}  // namespace

Json ImageGridJson(const ImageGrid& grid, const std::string& key,
                   const std::vector<double>& values) {
  Json out;
  out["cols"] = grid.cols;
  out["rows"] = grid.rows;
  out["step_px"] = {grid.step_x, grid.step_y};
  Json array = Json::array();
  for (double v : values) array.push_back(std::isfinite(v) ? Json(v) : Json());
  out[key] = array;
  return out;
}

Json SelectionReport(const Selection& s) {
  Json j;
  j["choice"] = s.choice;
  j["camera"] = s.camera.empty() ? Json() : Json(s.camera);
  Json candidates = Json::array();
  for (const Candidate& c : s.candidates)
    candidates.push_back({{"name", c.name},
                          {"parameters", c.parameters},
                          {"heldout_rms_px", c.failed.empty() ? Json(c.heldout_rms_px) : Json()},
                          {"fold_rms_px", Numbers(c.fold_rms_px)},
                          {"corners", c.corners},
                          {"excess_px", c.excess_px},
                          {"spread_px", c.spread_px},
                          {"failed", c.failed.empty() ? Json() : Json(c.failed)}});
  j["candidates"] = candidates;
  j["best"] = s.best < 0 ? Json() : Json(s.best);
  j["chosen"] = s.chosen < 0 ? Json() : Json(s.chosen);
  j["why"] = s.why;
  return j;
}

Json CameraReport(const CameraCalibration& c) {
  const CameraModel& m = c.model;
  Json j;
  j["name"] = c.name;
  j["rms_px"] = c.rms_px;
  j["heldout_rms_px"] = c.heldout_rms_px < 0 ? Json() : Json(c.heldout_rms_px);
  j["views"] = c.views;
  j["points"] = c.points;
  j["outliers"] = c.outliers;
  j.update(Fields([&](auto&& visit) { ForEachCameraField(m, visit); }));
  Json stddev = Json::object();
  for (size_t i = 0; i < c.stddev.size() && i < c.param_names.size(); ++i)
    stddev[c.param_names[i]] = c.stddev[i];
  j["stddev"] = stddev;
  j["invalid_points"] = c.invalid_points;
  j["view_rms"] = ViewRmsJson(c.view_rms);
  j["skipped"] = c.skipped;
  j["init_method"] = c.init_method;
  j["max_observed_radius"] = c.max_observed_radius;
  if (c.board_warp.free) {  // board_warp.h; millimetres
    Json warp;
    warp["x2_mm"] = 1e3 * c.board_warp.data[0];
    warp["y2_mm"] = 1e3 * c.board_warp.data[1];
    warp["centre_mm"] = 1e3 * c.board_warp.Centre();
    if (c.board_warp_stddev.size() == 2) {
      warp["stddev_x2_mm"] = 1e3 * c.board_warp_stddev[0];
      warp["stddev_y2_mm"] = 1e3 * c.board_warp_stddev[1];
    }
    j["board_warp"] = warp;
  }
  Json field_curve = Json::array();
  for (const FieldTrial& t : c.field_curve)
    field_curve.push_back({{"tilt", t.tilt}, {"cols", t.cols}, {"rows", t.rows},
                           {"smoothness", t.smoothness}, {"rms_px", t.rms_px},
                           {"heldout_rms_px", t.heldout_rms_px},
                           {"fold_rms_px", Numbers(t.fold_rms_px)}});
  j["field_curve"] = field_curve;
  j["field_chosen"] = c.field_chosen;
  if (const WarpChoice& w = c.warp_choice; w.made) {  // --board-warp auto
    Json choice;
    choice["kept"] = w.kept;
    choice["flat_heldout_rms_px"] = w.flat_heldout_px;
    choice["warped_heldout_rms_px"] = w.warped_heldout_px;
    choice["x2_mm"] = 1e3 * w.estimated[0];
    choice["y2_mm"] = 1e3 * w.estimated[1];
    if (w.stddev.size() == 2) {
      choice["stddev_x2_mm"] = 1e3 * w.stddev[0];
      choice["stddev_y2_mm"] = 1e3 * w.stddev[1];
    }
    j["board_warp_choice"] = choice;
  }
  const ResidualGrid& g = c.grid;
  Json grid;
  grid["rows"] = g.rows;
  grid["cols"] = g.cols;
  grid["count"] = g.count;
  std::vector<double> mx, my;
  for (const auto& v : g.mean) {
    mx.push_back(v.x());
    my.push_back(v.y());
  }
  grid["mean_x"] = Numbers(mx);
  grid["mean_y"] = Numbers(my);
  grid["rms"] = Numbers(g.rms);
  j["residual_grid"] = grid;
  j["heldout_fold_rms_px"] = Numbers(c.heldout_fold_rms_px);
  j["heldout_extrapolated_corners"] = c.heldout_extrapolated;
  if (!c.uncertainty.empty()) j["projection_uncertainty"] = UncertaintyReport(c.uncertainty);
  Json curve = Json::array();
  for (const KnotTrial& t : c.knot_curve)
    curve.push_back({{"knots", t.knots},
                     {"rms_px", t.rms_px},
                     {"heldout_rms_px", t.heldout_rms_px},
                     {"fold_rms_px", Numbers(t.fold_rms_px)}});
  j["knot_curve"] = curve;
  Json choices = Json::array();
  for (const Selection& selection : c.selections) choices.push_back(SelectionReport(selection));
  j["choices"] = choices;
  return j;
}

Json StereoReport(const StereoCalibration& s) {
  Json j;
  j["model"] = ModelName(s.model);
  j["cameras"] = {CameraReport(s.left)};
  j["flow"] = FlowName(s.flow);
  j["solve_seconds"] = s.solve_seconds;
  if (s.mono) return j;  // one camera: no right, no stereo
  j["cameras"].push_back(CameraReport(s.right));
  Json stereo;
  stereo["rms_px"] = s.rms_px;
  std::vector<double> R, T;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) R.push_back(s.R(r, c));
    T.push_back(s.T(r));
  }
  stereo["R"] = Numbers(R);
  stereo["T"] = Numbers(T);
  stereo["baseline_m"] = s.T.norm();
  stereo["views"] = s.views;
  stereo["inconsistent_views"] = s.inconsistent_views;
  stereo["half_turned_views"] = s.half_turned_views;
  stereo["view_rms"] = ViewRmsJson(s.view_rms);
  Json stddev = Json::object();
  for (size_t i = 0; i < s.extrinsic_stddev.size() && i < s.extrinsic_names.size(); ++i)
    stddev[s.extrinsic_names[i]] = s.extrinsic_stddev[i];
  stereo["stddev"] = stddev;
  j["stereo"] = stereo;
  return j;
}

Json ModelsReport(const ModelCalibrations& calibrations) {
  Json j;
  j["models"] = Json::array();
  for (const auto& c : calibrations.solved) j["models"].push_back(StereoReport(c));
  for (const auto& failure : calibrations.failed)
    j["models"].push_back({{"model", failure.model}, {"error", failure.error}});
  Json table = Json::array();
  for (const auto& row : TableRows(calibrations.solved, calibrations.chosen))
    table.push_back({{"model", row.model},
                     {"left_rms_px", row.left_rms},
                     {"right_rms_px", row.right_rms},
                     {"stereo_rms_px", row.stereo_rms},
                     {"left_heldout_rms_px", row.left_heldout},
                     {"right_heldout_rms_px", row.right_heldout},
                     {"coeffs", row.coeffs},
                     {"chosen", row.chosen}});
  j["table_ii"] = table;
  j["chosen"] = calibrations.solved.empty() ? Json() : Json(ModelName(Chosen(calibrations).model));
  j["model_choice"] = SelectionReport(calibrations.model_selection);
  j["solve_seconds"] = calibrations.solve_seconds;
  return j;
}

}  // namespace ws::calib
