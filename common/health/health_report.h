// stereo-health's report (--report FILE.json): the final figures and, after
// --refine, how the refinement changed dy.
//
//   {"verdict": "ok", "dy_median_px": 0.04, "dy_p95_px": 0.12, "matches": 4210, "frames": 5,
//    "max_dy_px": 0.3, "frames_checked": 5, "calibration": "calibration file calib.yaml",
//    "grid": {"rows": 3, "cols": 4, "dy_px": [[...], ...], "matches": [[...], ...]},
//    "refine": {"applied": true, "refused": "", "matches": 20000, "matches_used": 19800,
//               "rotation_change_deg": 0.2, "translation_direction_change_deg": 0.01,
//               "dy_median_before_px": 1.1, "dy_p95_before_px": 2.0,
//               "dy_median_after_px": 0.04, "dy_p95_after_px": 0.12,
//               "R": [9, row-major], "T": [3]}}
//
// The figures are those of the last CALIBRATION_HEALTH (the verdict's
// window); "refine" is there only after a refinement, its dy figures over
// the matches it used, before and after the correction.
#pragma once

#include <optional>

#include <nlohmann/json.hpp>

#include "health/extrinsic_refine.h"
#include "widestereo/calibration_health_t.hpp"

namespace ws {

nlohmann::ordered_json HealthReport(const widestereo::calibration_health_t& health, int frames_checked,
                                    const std::optional<RefineResult>& refine);

}  // namespace ws
