#include "health/health_report.h"

namespace ws {

nlohmann::ordered_json HealthReport(const widestereo::calibration_health_t& h, int frames_checked,
                                    const std::optional<RefineResult>& refine) {
  nlohmann::ordered_json j;
  j["verdict"] = h.verdict;
  j["dy_median_px"] = h.dy_median_px;
  j["dy_p95_px"] = h.dy_p95_px;
  j["matches"] = h.matches;
  j["frames"] = h.frames;
  j["max_dy_px"] = h.max_dy_px;
  j["frames_checked"] = frames_checked;
  j["calibration"] = h.calibration;
  j["grid"] = {{"rows", h.grid_rows}, {"cols", h.grid_cols}, {"dy_px", h.grid_dy_px},
               {"matches", h.grid_matches}};
  if (refine) {
    const RefineResult& r = *refine;
    std::vector<double> R, T;
    for (int i = 0; i < 9; ++i) R.push_back(r.rig.R(i / 3, i % 3));
    for (int i = 0; i < 3; ++i) T.push_back(r.rig.T(i));
    j["refine"] = {{"applied", r.applied},
                   {"refused", r.refused},
                   {"matches", r.matches},
                   {"matches_used", r.matches_used},
                   {"rotation_change_deg", r.rotation_change_deg},
                   {"translation_direction_change_deg", r.translation_direction_change_deg},
                   {"dy_median_before_px", r.dy_median_before},
                   {"dy_p95_before_px", r.dy_p95_before},
                   {"dy_median_after_px", r.dy_median_after},
                   {"dy_p95_after_px", r.dy_p95_after},
                   {"R", R},
                   {"T", T}};
  }
  return j;
}

}  // namespace ws
